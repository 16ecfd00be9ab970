//! The priority tier of a constraint: which constraints give way first when the whole set
//! cannot be met (the lexicographic solve of the policy meets the tiers in order).

/// A priority tier: 0 (the default) is required; higher tiers are relaxed first.
pub type Priority = u8;
