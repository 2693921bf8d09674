//! What a run writes into its output folder: the trajectory ([`trajectory`], CSV), the
//! summary ([`summary`], JSON), the plots ([`plots`], SVG) and the 3-D view ([`view`], one
//! HTML page), into a folder taken for the run alone ([`folder`]), with a scene's title in the
//! form each can hold ([`text`]). Only the command-line tool
//! writes these, so the module comes with the `cli` feature, and a library user who turns it
//! off builds neither the CSV writer nor the plotting library.

pub mod folder;
pub mod plots;
pub mod summary;
pub mod text;
pub mod trajectory;
pub mod view;
