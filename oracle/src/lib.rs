//! Oracle (in progress).
