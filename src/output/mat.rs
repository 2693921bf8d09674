//! MAT-files: MATLAB's Level 5 format (the v6 and v7 `save` formats without compression),
//! which MATLAB's `load` and `scipy.io.loadmat` read. Only what a linear model
//! needs is written: matrices of doubles, strings (char row vectors) and cell arrays of
//! strings, little-endian, uncompressed.
//!
//! Why a writer of its own: the pure-Rust crates were weighed and none fits. `matfile` reads
//! only. `matrw` (0.1.x, its API declared unstable) writes only to a path, drops the errors
//! of its writes (a full disk gives a cut file and `Ok`), and stamps the local time into the
//! header, so the same model would give different files; `matio-rs` binds the C library. The
//! part of the format used here is small and fixed, in MathWorks' "MAT-File Format" (the
//! Level 5 chapter):
//!
//! - a 128-byte header: 116 bytes of text starting `MATLAB 5.0 MAT-file`, 8 bytes of
//!   subsystem offset (zero: none), the version 0x0100 and the endian indicator `IM`;
//! - then one data element per variable: an 8-byte tag (the data type and the number of
//!   bytes, two u32) followed by the data, padded with zeros to a multiple of 8 bytes;
//! - a variable is a `miMATRIX` element holding four sub-elements: the array flags (its
//!   class), the dimensions, the name and the data, column by column. A cell array's data
//!   are `miMATRIX` elements with empty names, one per cell.
//!
//! Strings are written as UTF-16 (`miUTF16`), one dimension per UTF-16 unit, as MATLAB counts
//! a char array's characters. Of the encodings the format allows for character data, it is
//! the one both scipy and Octave read back whole beyond ASCII (a title's `°`): scipy decodes
//! `miUINT16` data as bytes and garbles such a character, and Octave reads `miUTF8` data one
//! byte per dimension, cutting a string short by its extra bytes. Every double is written as
//! its eight bytes, so it reads back to the same bits.

use nalgebra::DMatrix;

/// A variable's value.
#[derive(Debug, Clone, PartialEq)]
pub enum MatValue {
    /// A matrix of doubles.
    Matrix(DMatrix<f64>),
    /// A string: a char row vector.
    Text(String),
    /// A column of cells, each a string.
    Texts(Vec<String>),
}

/// Why a MAT-file could not be written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MatError {
    /// A name MATLAB cannot load: a letter, then letters, digits and `_`, at most 63.
    #[error("`{0}` is not a MATLAB variable name")]
    Name(String),
    /// A variable too large for a Level 5 element (4 GiB).
    #[error("`{0}` is too large for a MAT-file's element")]
    TooLarge(String),
}

/// The data types of the format's tags.
mod data_type {
    pub const INT8: u32 = 1;
    pub const INT32: u32 = 5;
    pub const UINT32: u32 = 6;
    pub const DOUBLE: u32 = 9;
    pub const MATRIX: u32 = 14;
    pub const UTF16: u32 = 17;
}

/// The array classes of the array flags.
mod class {
    pub const CELL: u32 = 1;
    pub const CHAR: u32 = 4;
    pub const DOUBLE: u32 = 6;
}

/// The header's text field, in bytes.
const TEXT: usize = 116;

/// The bytes of a MAT-file holding `variables`, in their order.
///
/// ```
/// use eom::output::mat::{MatValue, mat_file};
/// let bytes = mat_file(&[("title", MatValue::Text("Pendulum".into()))]).unwrap();
/// assert!(bytes.starts_with(b"MATLAB 5.0 MAT-file"));
/// assert_eq!(&bytes[124..128], &[0x00, 0x01, b'I', b'M']);
/// assert_eq!(bytes.len() % 8, 0);
/// ```
pub fn mat_file(variables: &[(&str, MatValue)]) -> Result<Vec<u8>, MatError> {
    let mut bytes = header();
    for (name, value) in variables {
        if !is_variable_name(name) {
            return Err(MatError::Name((*name).to_owned()));
        }
        let too_large = || MatError::TooLarge((*name).to_owned());
        bytes.extend(array(name, value).ok_or_else(too_large)?);
    }
    Ok(bytes)
}

/// The 128-byte header of a little-endian Level 5 file, without a timestamp, so that the same
/// variables give the same bytes.
fn header() -> Vec<u8> {
    let mut bytes = b"MATLAB 5.0 MAT-file, written by eom".to_vec();
    bytes.resize(TEXT, b' ');
    bytes.extend([0; 8]);
    bytes.extend(0x0100u16.to_le_bytes());
    bytes.extend(*b"IM");
    bytes
}

/// What MATLAB accepts as a variable's name.
fn is_variable_name(name: &str) -> bool {
    let mut characters = name.chars();
    characters.next().is_some_and(|c| c.is_ascii_alphabetic())
        && characters.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && name.len() <= 63
}

/// One `miMATRIX` element; `None` where a size does not fit its field.
fn array(name: &str, value: &MatValue) -> Option<Vec<u8>> {
    let mut body = Vec::new();
    let (class, dimensions) = match value {
        MatValue::Matrix(matrix) => (class::DOUBLE, [matrix.nrows(), matrix.ncols()]),
        MatValue::Text(text) => (class::CHAR, text_dimensions(text)),
        MatValue::Texts(texts) => (class::CELL, [texts.len(), 1]),
    };
    element(
        &mut body,
        data_type::UINT32,
        &[class, 0].map(u32::to_le_bytes).concat(),
    )?;
    let dimensions: Vec<u8> = (dimensions.iter())
        .map(|&d| i32::try_from(d).ok().map(i32::to_le_bytes))
        .collect::<Option<Vec<_>>>()?
        .concat();
    element(&mut body, data_type::INT32, &dimensions)?;
    element(&mut body, data_type::INT8, name.as_bytes())?;
    match value {
        // nalgebra stores a matrix column by column, as the format does.
        MatValue::Matrix(matrix) => {
            let data: Vec<u8> = matrix.iter().flat_map(|v| v.to_le_bytes()).collect();
            element(&mut body, data_type::DOUBLE, &data)?;
        }
        MatValue::Text(text) => {
            let data: Vec<u8> = text.encode_utf16().flat_map(u16::to_le_bytes).collect();
            element(&mut body, data_type::UTF16, &data)?;
        }
        MatValue::Texts(texts) => {
            for text in texts {
                body.extend(array("", &MatValue::Text(text.clone()))?);
            }
        }
    }
    let mut bytes = Vec::with_capacity(body.len() + 8);
    element(&mut bytes, data_type::MATRIX, &body)?;
    Some(bytes)
}

/// A string's dimensions: one row of its UTF-16 units, or 0 × 0 for the empty string (as
/// MATLAB writes `''`).
fn text_dimensions(text: &str) -> [usize; 2] {
    match text.encode_utf16().count() {
        0 => [0, 0],
        n => [1, n],
    }
}

/// Appends a data element: its tag, `data`, and zeros to the next multiple of 8 bytes.
fn element(out: &mut Vec<u8>, data_type: u32, data: &[u8]) -> Option<()> {
    let size = u32::try_from(data.len()).ok()?;
    out.extend(data_type.to_le_bytes());
    out.extend(size.to_le_bytes());
    out.extend(data);
    out.resize(out.len().next_multiple_of(8), 0);
    Some(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The u32 at `at`, little-endian.
    fn word(bytes: &[u8], at: usize) -> u32 {
        u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap())
    }

    #[test]
    fn a_matrix_is_one_element_of_flags_dimensions_name_and_columns() {
        let matrix = DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 3.0, -0.0]);
        let bytes = mat_file(&[("A", MatValue::Matrix(matrix))]).unwrap();
        let at = 128;
        // The miMATRIX tag: its size is everything after the tag.
        assert_eq!(word(&bytes, at), data_type::MATRIX);
        assert_eq!(word(&bytes, at + 4) as usize, bytes.len() - at - 8);
        // The array flags: the double class, no flags; nzmax 0.
        assert_eq!(
            [word(&bytes, at + 8), word(&bytes, at + 12)],
            [data_type::UINT32, 8]
        );
        assert_eq!([word(&bytes, at + 16), word(&bytes, at + 20)], [6, 0]);
        // The dimensions, 2 × 2.
        assert_eq!([word(&bytes, at + 24), word(&bytes, at + 28)], [5, 8]);
        assert_eq!([word(&bytes, at + 32), word(&bytes, at + 36)], [2, 2]);
        // The name, "A", padded to 8 bytes.
        assert_eq!([word(&bytes, at + 40), word(&bytes, at + 44)], [1, 1]);
        assert_eq!(&bytes[at + 48..at + 56], b"A\0\0\0\0\0\0\0");
        // The data, column by column, each double's own bits (−0 kept).
        assert_eq!([word(&bytes, at + 56), word(&bytes, at + 60)], [9, 32]);
        let data: Vec<u64> = (0..4)
            .map(|k| u64::from_le_bytes(bytes[at + 64 + 8 * k..][..8].try_into().unwrap()))
            .collect();
        let expected = [1.0f64, 3.0, 2.0, -0.0].map(f64::to_bits);
        assert_eq!(data, expected);
        assert_eq!(bytes.len(), at + 96);
    }

    #[test]
    fn a_cell_of_strings_holds_one_unnamed_char_array_per_cell() {
        let names = MatValue::Texts(vec!["u".into(), "psi".into()]);
        let bytes = mat_file(&[("x_names", names)]).unwrap();
        let at = 128;
        assert_eq!(word(&bytes, at + 16), class::CELL);
        assert_eq!([word(&bytes, at + 32), word(&bytes, at + 36)], [2, 1]);
        // After the name "x_names" (7 bytes, padded to 8), the first cell.
        let cell = at + 56;
        assert_eq!(word(&bytes, cell), data_type::MATRIX);
        assert_eq!(word(&bytes, cell + 8 + 8), class::CHAR);
        // Its name is empty: a tag of no bytes.
        assert_eq!([word(&bytes, cell + 40), word(&bytes, cell + 44)], [1, 0]);
        // Its text, UTF-16: one unit, two bytes.
        assert_eq!([word(&bytes, cell + 48), word(&bytes, cell + 52)], [17, 2]);
        assert_eq!(&bytes[cell + 56..cell + 58], b"u\0");
    }

    #[test]
    fn a_string_counts_utf16_units_not_bytes() {
        assert_eq!(text_dimensions("+4°"), [1, 3]);
        assert_eq!(text_dimensions(""), [0, 0]);
        // Beyond the basic plane a character is two units, as MATLAB counts it.
        assert_eq!(text_dimensions("𝜓"), [1, 2]);
    }

    #[test]
    fn a_name_matlab_cannot_load_is_refused() {
        let value = MatValue::Text(String::new());
        for name in ["1A", "", "x-names", "ψ"] {
            assert_eq!(
                mat_file(&[(name, value.clone())]),
                Err(MatError::Name(name.into()))
            );
        }
        assert!(mat_file(&[("x_names_2", value)]).is_ok());
    }
}
