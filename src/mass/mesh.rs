//! Solid bodies from closed triangle meshes (STL files from CAD), by the divergence theorem.
//!
//! A closed, consistently oriented triangle mesh bounds a solid. Joining every triangle to one
//! reference point cuts the solid into signed tetrahedra whose volumes, first moments and second
//! moments add up to the solid's exactly (the divergence theorem in discrete form), for any
//! polyhedron, convex or not. Triangles whose normals point inwards give a negative total; this
//! module refuses such a mesh rather than flipping it silently, because an inside-out mesh
//! usually means a wrong export that the user should see.
//!
//! The mesh must be closed and consistently oriented: every edge is used exactly once in each
//! direction (once by the triangle on either side). Anything else gives a wrong volume, so it is
//! an error that names the edge. Several closed shells are allowed: a shell wound inwards inside
//! another is a cavity, whose volume and moments the sum subtracts.

use super::error::MassError;
use super::properties::MassProperties;
use crate::InertiaTensor;
use crate::validate::positive;
use nalgebra::{Matrix3, Vector3};
use std::collections::BTreeMap;
use std::io::{BufRead, BufReader, Read, Seek, SeekFrom, Write};
use std::path::Path;
use thiserror::Error;

/// Why a mesh does not describe a solid.
#[derive(Debug, Error)]
pub enum MeshError {
    /// The STL file could not be opened or parsed.
    #[error("cannot read STL: {0}")]
    Read(std::io::Error),
    /// The mesh has no triangles.
    #[error("the mesh has no triangles")]
    Empty,
    /// A vertex has a NaN or infinite coordinate.
    #[error("vertex {vertex} has a coordinate that is not finite: {position:?}")]
    NotFiniteVertex {
        /// Index of the vertex.
        vertex: usize,
        /// Its coordinates.
        position: [f64; 3],
    },
    /// A triangle refers to a vertex that does not exist.
    #[error("triangle {triangle} refers to vertex {vertex}, but there are only {count} vertices")]
    VertexOutOfRange {
        /// Index of the triangle.
        triangle: usize,
        /// The missing vertex index.
        vertex: usize,
        /// How many vertices there are.
        count: usize,
    },
    /// A triangle uses the same vertex twice.
    #[error("triangle {triangle} uses the same vertex twice")]
    DegenerateTriangle {
        /// Index of the triangle.
        triangle: usize,
    },
    /// An edge has a triangle on one side only: the mesh has a hole.
    #[error("the mesh is not closed: edge {from:?} → {to:?} has no triangle on its other side")]
    NotClosed {
        /// One end of the edge.
        from: [f64; 3],
        /// The other end.
        to: [f64; 3],
    },
    /// An edge is used twice in the same direction.
    #[error(
        "the mesh is not consistently oriented: edge {from:?} → {to:?} is used {count} times in \
         the same direction (neighbouring triangles must run through a shared edge in opposite \
         directions, and no more than two triangles may meet at an edge)"
    )]
    NotOriented {
        /// One end of the edge.
        from: [f64; 3],
        /// The other end.
        to: [f64; 3],
        /// How many triangles use it in this direction.
        count: usize,
    },
    /// The normals point inwards: the enclosed volume comes out negative.
    #[error(
        "the mesh is inside out (its triangles' normals point inwards, volume {volume}); \
         reverse the winding of every triangle"
    )]
    InsideOut {
        /// The signed volume computed.
        volume: f64,
    },
    /// The mesh encloses no volume.
    #[error("the mesh encloses no volume")]
    ZeroVolume,
    /// The mass or density given is not physical, or the tensor is not.
    #[error(transparent)]
    Mass(#[from] MassError),
}

/// How much a mesh weighs: a uniform density, or a total mass spread uniformly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MeshMass {
    /// Mass per unit volume, in the mesh's length unit.
    Density(f64),
    /// The total mass.
    Total(f64),
}

/// A closed, consistently oriented triangle mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    vertices: Vec<Vector3<f64>>,
    triangles: Vec<[usize; 3]>,
}

/// Volume, first and second moments of a solid about a reference point.
struct Moments {
    volume: f64,
    first: Vector3<f64>,
    second: Matrix3<f64>,
}

impl Mesh {
    /// Builds a mesh from vertices and triangles (vertex indices, counter-clockwise seen from
    /// outside), refusing one that is not closed or not consistently oriented.
    pub fn new(vertices: Vec<Vector3<f64>>, triangles: Vec<[usize; 3]>) -> Result<Self, MeshError> {
        check_vertices(&vertices)?;
        check_triangles(&triangles, vertices.len())?;
        check_edges(&vertices, &triangles)?;
        Ok(Self {
            vertices,
            triangles,
        })
    }

    /// Reads an ASCII or binary STL. Vertices with identical coordinates are merged, which is
    /// what joins the triangles into a surface; `-0` and `0` count as the same coordinate, as
    /// CAD exporters write both.
    ///
    /// A file whose first line starts with `solid ` is ASCII, anything else binary (as
    /// `stl_io` decides). ASCII coordinates are read to the nearest f64 (`stl_io` would read
    /// them as f32, which is wrong in the eighth digit and refuses anything beyond f32's
    /// range); binary ones are f32 in the file and exact in f64.
    pub fn read_stl<R: Read + Seek>(reader: &mut R) -> Result<Self, MeshError> {
        let triangles = if is_ascii_stl(reader).map_err(MeshError::Read)? {
            read_ascii_stl(BufReader::new(reader)).map_err(MeshError::Read)?
        } else {
            let mut triangles = Vec::new();
            for triangle in stl_io::create_stl_reader(reader).map_err(MeshError::Read)? {
                let triangle = triangle.map_err(MeshError::Read)?;
                triangles.push(triangle.vertices.map(|v| v.0.map(f64::from)));
            }
            triangles
        };
        let mut index: BTreeMap<[u64; 3], usize> = BTreeMap::new();
        let mut vertices = Vec::new();
        let triangles = triangles
            .into_iter()
            .map(|triangle| {
                triangle.map(|v| {
                    // Adding +0 turns -0 into +0 and leaves every other value as it is.
                    let key = v.map(|x| (x + 0.0).to_bits());
                    *index.entry(key).or_insert_with(|| {
                        vertices.push(Vector3::from(v));
                        vertices.len() - 1
                    })
                })
            })
            .collect();
        Self::new(vertices, triangles)
    }

    /// Reads an STL file.
    pub fn load_stl(path: &Path) -> Result<Self, MeshError> {
        Self::read_stl(&mut std::fs::File::open(path).map_err(MeshError::Read)?)
    }

    /// Writes the mesh as a binary STL (coordinates rounded to `f32`, as the format stores them).
    pub fn write_stl<W: Write>(&self, writer: &mut W) -> std::io::Result<()> {
        let triangles: Vec<stl_io::Triangle> = self.triangles.iter().map(|t| self.stl(t)).collect();
        stl_io::write_stl(writer, triangles.iter())
    }

    /// The vertices, in the order they first appear (in the file, for a mesh read from STL).
    pub fn vertices(&self) -> &[Vector3<f64>] {
        &self.vertices
    }

    /// The number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// The enclosed volume.
    pub fn volume(&self) -> f64 {
        self.moments().volume
    }

    /// Mass, G and tensor about G of the uniform solid the mesh bounds, in the mesh's axes.
    ///
    /// ```
    /// use eom::mass::{Mesh, MeshMass};
    /// use nalgebra::Vector3;
    /// // A tetrahedron with its right angle at the origin: volume 1/6, G at (1/4, 1/4, 1/4).
    /// let vertices = vec![Vector3::zeros(), Vector3::x(), Vector3::y(), Vector3::z()];
    /// let mesh = Mesh::new(vertices, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]).unwrap();
    /// let body = mesh.mass_properties(MeshMass::Density(6.0)).unwrap();
    /// assert!((body.mass() - 1.0).abs() < 1e-15);
    /// assert!((body.centre_of_gravity() - Vector3::repeat(0.25)).norm() < 1e-15);
    /// ```
    pub fn mass_properties(&self, mass: MeshMass) -> Result<MassProperties, MeshError> {
        let moments = self.moments();
        if moments.volume < 0.0 {
            return Err(MeshError::InsideOut {
                volume: moments.volume,
            });
        }
        if moments.volume == 0.0 {
            return Err(MeshError::ZeroVolume);
        }
        let density = match mass {
            MeshMass::Density(rho) => positive("density", rho),
            MeshMass::Total(total) => positive("mass", total).map(|m| m / moments.volume),
        }
        .map_err(MassError::from)?;
        let centre = moments.first / moments.volume;
        let second_about_g =
            (moments.second - centre * centre.transpose() * moments.volume) * density;
        let inertia = Matrix3::identity() * second_about_g.trace() - second_about_g;
        let inertia = InertiaTensor::from_matrix(inertia).map_err(MassError::from)?;
        let origin = self.reference_point();
        Ok(MassProperties::new(
            density * moments.volume,
            origin + centre,
            inertia,
        )?)
    }

    /// The mean of the vertices: integrating about a point inside the body rather than the
    /// file's origin keeps the digits that a part far from the origin would otherwise lose.
    fn reference_point(&self) -> Vector3<f64> {
        self.vertices.iter().sum::<Vector3<f64>>() / self.vertices.len() as f64
    }

    /// Sums the signed tetrahedra (reference point, a, b, c): volume `a·(b×c)/6`, first moment
    /// `V (a + b + c)/4`, second moments `∫ r rᵀ dV = V/20 (a aᵀ + b bᵀ + c cᵀ + s sᵀ)` with
    /// `s = a + b + c`, all relative to the reference point.
    fn moments(&self) -> Moments {
        let origin = self.reference_point();
        let mut sum = Moments {
            volume: 0.0,
            first: Vector3::zeros(),
            second: Matrix3::zeros(),
        };
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| self.vertices[i] - origin);
            let volume = a.dot(&b.cross(&c)) / 6.0;
            let s = a + b + c;
            let outer =
                a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose();
            sum.volume += volume;
            sum.first += s * (volume / 4.0);
            sum.second += outer * (volume / 20.0);
        }
        sum
    }

    fn stl(&self, t: &[usize; 3]) -> stl_io::Triangle {
        let [a, b, c] = t.map(|i| self.vertices[i]);
        let normal = (b - a).cross(&(c - a)).normalize();
        let f32s = |v: Vector3<f64>| [v.x as f32, v.y as f32, v.z as f32];
        stl_io::Triangle {
            normal: stl_io::Normal::new(f32s(normal)),
            vertices: [a, b, c].map(|v| stl_io::Vertex::new(f32s(v))),
        }
    }
}

/// Whether an STL is ASCII: its first line is text that starts with `solid ` (the test that
/// `stl_io` makes, so that a binary file is read by it as before). The reader is left at the
/// start.
fn is_ascii_stl<R: Read + Seek>(reader: &mut R) -> std::io::Result<bool> {
    let mut first = String::new();
    let read = BufReader::new(&mut *reader).read_line(&mut first);
    reader.seek(SeekFrom::Start(0))?;
    Ok(read.is_ok() && first.starts_with("solid "))
}

/// A triangle's corners as read, before equal corners are merged.
type Corners = [[f64; 3]; 3];

/// Reads the triangles of an ASCII STL, every coordinate to the nearest f64:
///
/// ```text
/// solid NAME
///   facet normal nx ny nz
///     outer loop
///       vertex x y z      (three times)
///     endloop
///   endfacet              (once per triangle)
/// endsolid NAME
/// ```
///
/// Tokens are separated by any whitespace and blank lines are skipped; anything after
/// `endsolid` is ignored. The normals are checked as numbers but not used (the winding says
/// which side is out).
fn read_ascii_stl(reader: impl BufRead) -> std::io::Result<Vec<Corners>> {
    let mut lines = AsciiLines {
        lines: reader.lines(),
        number: 0,
    };
    let (_, header) = lines.next("`solid`")?;
    if !header.starts_with("solid ") {
        return Err(invalid("an ASCII STL starts with `solid `".into()));
    }
    let mut triangles = Vec::new();
    loop {
        let (number, line) = lines.next("`facet normal` or `endsolid`")?;
        let tokens: Vec<&str> = line.split_ascii_whitespace().collect();
        if tokens[0] == "endsolid" {
            return Ok(triangles);
        }
        if tokens.len() != 5 || tokens[..2] != ["facet", "normal"] {
            return Err(at(number, &line, "expected `facet normal nx ny nz`"));
        }
        coordinates(&tokens[2..]).map_err(|e| at(number, &line, &e))?;
        lines.expect(&["outer", "loop"])?;
        let mut corners = [[0.0; 3]; 3];
        for corner in &mut corners {
            let (number, line) = lines.next("`vertex x y z`")?;
            let tokens: Vec<&str> = line.split_ascii_whitespace().collect();
            if tokens.len() != 4 || tokens[0] != "vertex" {
                return Err(at(number, &line, "expected `vertex x y z`"));
            }
            *corner = coordinates(&tokens[1..]).map_err(|e| at(number, &line, &e))?;
        }
        lines.expect(&["endloop"])?;
        lines.expect(&["endfacet"])?;
        triangles.push(corners);
    }
}

/// The non-blank lines of an ASCII STL, with their line numbers.
struct AsciiLines<B> {
    lines: std::io::Lines<B>,
    number: usize,
}

impl<B: BufRead> AsciiLines<B> {
    /// The next non-blank line and its number; the end of the file is an error that says
    /// what was expected.
    fn next(&mut self, expecting: &str) -> std::io::Result<(usize, String)> {
        for line in self.lines.by_ref() {
            self.number += 1;
            let line = line?;
            if line.split_ascii_whitespace().next().is_some() {
                return Ok((self.number, line));
            }
        }
        Err(std::io::Error::new(
            std::io::ErrorKind::UnexpectedEof,
            format!("the ASCII STL ends while expecting {expecting}"),
        ))
    }

    /// The next non-blank line, which must be these words.
    fn expect(&mut self, words: &[&str]) -> std::io::Result<()> {
        let expected = format!("`{}`", words.join(" "));
        let (number, line) = self.next(&expected)?;
        if line.split_ascii_whitespace().eq(words.iter().copied()) {
            Ok(())
        } else {
            Err(at(number, &line, &format!("expected {expected}")))
        }
    }
}

fn invalid(message: String) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidData, message)
}

/// What is wrong at a line of an ASCII STL, quoting it.
fn at(number: usize, line: &str, what: &str) -> std::io::Error {
    invalid(format!("line {number}: {what}, got {:?}", line.trim()))
}

/// Three finite numbers, each read to the nearest f64 (`f64::from_str` rounds correctly).
fn coordinates(tokens: &[&str]) -> Result<[f64; 3], String> {
    let mut xyz = [0.0; 3];
    for (x, token) in xyz.iter_mut().zip(tokens) {
        *x = token
            .parse::<f64>()
            .map_err(|e| format!("`{token}` is not a number ({e})"))?;
        if !x.is_finite() {
            return Err(format!("`{token}` is not a finite number"));
        }
    }
    Ok(xyz)
}

fn check_vertices(vertices: &[Vector3<f64>]) -> Result<(), MeshError> {
    match vertices
        .iter()
        .position(|v| !v.iter().all(|x| x.is_finite()))
    {
        Some(vertex) => Err(MeshError::NotFiniteVertex {
            vertex,
            position: vertices[vertex].into(),
        }),
        None => Ok(()),
    }
}

fn check_triangles(triangles: &[[usize; 3]], count: usize) -> Result<(), MeshError> {
    if triangles.is_empty() {
        return Err(MeshError::Empty);
    }
    for (triangle, &[a, b, c]) in triangles.iter().enumerate() {
        if let Some(&vertex) = [a, b, c].iter().find(|&&v| v >= count) {
            return Err(MeshError::VertexOutOfRange {
                triangle,
                vertex,
                count,
            });
        }
        if a == b || b == c || c == a {
            return Err(MeshError::DegenerateTriangle { triangle });
        }
    }
    Ok(())
}

/// Every directed edge must appear exactly once and its reverse exactly once. A `BTreeMap`
/// keeps the edge reported first the same from run to run.
fn check_edges(vertices: &[Vector3<f64>], triangles: &[[usize; 3]]) -> Result<(), MeshError> {
    let mut uses: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for &[a, b, c] in triangles {
        for edge in [(a, b), (b, c), (c, a)] {
            *uses.entry(edge).or_default() += 1;
        }
    }
    let point = |i: usize| -> [f64; 3] { vertices[i].into() };
    for (&(from, to), &count) in &uses {
        if count > 1 {
            let (from, to) = (point(from), point(to));
            return Err(MeshError::NotOriented { from, to, count });
        }
        if !uses.contains_key(&(to, from)) {
            let (from, to) = (point(from), point(to));
            return Err(MeshError::NotClosed { from, to });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit tetrahedron as ASCII STL, its corner (1, 0, 0) written as `x`.
    fn tetrahedron(x: &str) -> String {
        let corners = [
            [["0", "0", "0"], ["0", "1", "0"], [x, "0", "0"]],
            [["0", "0", "0"], [x, "0", "0"], ["0", "0", "1"]],
            [["0", "0", "0"], ["0", "0", "1"], ["0", "1", "0"]],
            [[x, "0", "0"], ["0", "1", "0"], ["0", "0", "1"]],
        ];
        let mut text = String::from("solid t\n\n");
        for facet in corners {
            text += "  facet normal 0 0 0\n    outer loop\n";
            for [a, b, c] in facet {
                text += &format!("      vertex {a}\t{b} {c}\n");
            }
            text += "    endloop\n  endfacet\n";
        }
        text + "endsolid t\n"
    }

    fn read(text: &str) -> Result<Mesh, MeshError> {
        Mesh::read_stl(&mut std::io::Cursor::new(text.as_bytes()))
    }

    #[test]
    fn ascii_coordinates_are_the_nearest_f64_not_f32() {
        // 0.1 as f32 is 0.100000001490116…; 1e39 is beyond f32.
        for (text, x) in [
            ("0.1", 0.1),
            ("1e39", 1e39),
            ("1.5707962967948965", 1.5707962967948965),
        ] {
            let mesh = read(&tetrahedron(text)).unwrap();
            assert_eq!(mesh.vertices()[2].x.to_bits(), f64::to_bits(x), "{text}");
        }
    }

    #[test]
    fn ascii_faults_name_the_line() {
        let message = |text: &str| read(text).unwrap_err().to_string();
        let text = tetrahedron("1").replacen("vertex 1\t0 0", "vertex 1 O 0", 1);
        let error = message(&text);
        assert!(
            error.contains("line 7") && error.contains("`O` is not a number"),
            "{error}"
        );
        let error = message(&tetrahedron("inf"));
        assert!(error.contains("`inf` is not a finite number"), "{error}");
        let error = message(&tetrahedron("1").replacen("endloop", "end loop", 1));
        assert!(error.contains("line 8: expected `endloop`"), "{error}");
        let error = message(&tetrahedron("1").replace("endsolid t\n", ""));
        assert!(
            error.contains("ends while expecting `facet normal`"),
            "{error}"
        );
    }
}
