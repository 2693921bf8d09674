//! What a run writes into its output folder: the trajectory ([`trajectory`], CSV), the
//! summary ([`summary`], JSON) and the plots ([`plots`], SVG), with a scene's title in the
//! form each can hold ([`text`]). Only the command-line tool
//! writes these, so the module comes with the `cli` feature, and a library user who turns it
//! off builds neither the CSV writer nor the plotting library.

pub mod plots;
pub mod summary;
pub mod text;
pub mod trajectory;
