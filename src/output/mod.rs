//! What a run writes: the trajectory (CSV), the summary (JSON) and the plots (SVG).

pub mod summary;
pub mod trajectory;
