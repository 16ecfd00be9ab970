#[cfg(test)]
mod encoding;

#[cfg(test)]
mod integration;

#[cfg(test)]
mod pointers;
