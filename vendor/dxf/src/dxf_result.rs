use crate::DxfError;

pub type DxfResult<T> = Result<T, DxfError>;
