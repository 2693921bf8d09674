//! What a run writes into its output folder: the trajectory ([`trajectory`], CSV) and the
//! summary ([`summary`], JSON), into a folder taken for the run alone ([`folder`]), with a
//! scene's title in the form each can hold ([`text`]); and MAT-files for MATLAB ([`mat`]). The
//! `eom` command adds its plots and its 3-D view (crate `eom-cli`); what is here needs none of
//! the command's crates, so a program that runs scenes writes the same files the command does.

pub mod drawing;
pub mod folder;
pub mod mat;
pub mod summary;
pub mod text;
pub mod trajectory;
