//! What a run leaves in its output folder besides the numbers: for now the SVG plots
//! ([`plots`]). Only the command-line tool writes these, so the module comes with the `cli`
//! feature, and a library user who turns it off does not build the plotting library.

pub mod plots;
