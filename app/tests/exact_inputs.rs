//! Every number of every input is read to the nearest binary64: `eom eval`'s JSON, scene files
//! (one at a time, and a sample as a sweep), body files, ASCII and binary STL meshes and
//! command-line flags. Each path reads the same 10⁵ random doubles, each written as Rust's
//! shortest round-trip form `{:?}`, as `{}` where that is other text (1e300 as 301 digits,
//! 1.0 as `1`), and with 17 significant digits `{:.16e}`, and must give back the same bits;
//! and 3000 decimals that sit exactly halfway between two neighbouring doubles, or a hair
//! below or above, which must round to even, down and up.
//!
//! The doubles cover every exponent (random bits), subnormals, the neighbourhood of ±π/2
//! (every double within 16 ulps, and offsets from 1e-12 to 1e-6 rad on both sides), where one
//! ulp of pitch is a relative change of ε/|cos θ| in the Euler rates, and a few special values.
//! Paths that read whole files get many numbers per file, so the test runs in seconds in a
//! debug build.
//!
//! `--nocapture` prints, per path, how many numbers each kind of text got wrong (all zero, or
//! the test fails). Before serde_json's `float_roundtrip` the JSON path read 60 077 of its
//! 271 146 texts wrong (a fifth to a third of each class, and two `{}` texts of ±f64::MAX
//! refused as out of range); before `Mesh` read ASCII STL itself rather than through f32, the
//! mesh path read 271 110 wrong, 66 195 of them refused as beyond f32. TOML (scenes, body
//! files) and the command line were right already.

use eom::kinds::body::BodyScene;
use eom::mass::{BodyFile, Mesh};
use eom::scene::sweep;
use eom_cli::eval::{SpatialInput, parse};
use std::collections::BTreeMap;
use std::f64::consts::FRAC_PI_2;
use std::fmt::Write as _;
use std::path::Path;
use std::sync::LazyLock;

use eom_test_support::cli::{eom_command, root};
use eom_test_support::random::Random;

/// Random doubles per path (each written three ways).
const VALUES: usize = 100_000;
/// Decimals at or next to a halfway point between two doubles, per path.
const TIES: usize = 1_000;

/// Where a value comes from, for the report.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Class {
    /// Random bits: every exponent, both signs.
    AnyExponent,
    /// Exponent field zero.
    Subnormal,
    /// Within 16 ulps of ±π/2.
    UlpsFromVertical,
    /// ±π/2 ± 10^U(−12, −6).
    NearVertical,
    /// Zeros, extremes, powers of two, short decimals.
    Special,
    /// A decimal exactly halfway between two doubles: rounds to the even one.
    Tie,
    /// A halfway decimal cut short: rounds towards zero.
    BelowTie,
    /// A halfway decimal with a 1 far behind it: rounds away from zero.
    AboveTie,
}

/// How a value is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Form {
    /// `{:?}`: shortest round trip, with an exponent for very large and very small values.
    Debug,
    /// `{}`: shortest round trip, never with an exponent (1e300 is 301 digits).
    Display,
    /// `{:.16e}`: 17 significant digits.
    Digits17,
    /// A long decimal made for rounding (the tie classes).
    Long,
}

/// One number as text, and the double it must be read as.
#[derive(Debug, Clone)]
struct Number {
    expected: f64,
    text: String,
    class: Class,
    form: Form,
}

fn double(rng: &mut Random, class: Class) -> f64 {
    match class {
        Class::AnyExponent => loop {
            let x = f64::from_bits(rng.next());
            if x.is_finite() {
                return x;
            }
        },
        Class::Subnormal => {
            let mantissa = 1 + rng.below((1u64 << 52) - 1);
            rng.sign() * f64::from_bits(mantissa)
        }
        Class::NearVertical => {
            let offset = 10f64.powf(-12.0 + 6.0 * rng.unit());
            rng.sign() * (FRAC_PI_2 + rng.sign() * offset)
        }
        _ => unreachable!("listed, not drawn"),
    }
}

/// Every double within 16 ulps of ±π/2, and the special values.
fn listed() -> Vec<(f64, Class)> {
    let mut values = Vec::new();
    for sign in [1.0, -1.0] {
        let centre = (sign * FRAC_PI_2).to_bits() as i64;
        for k in -16..=16 {
            values.push((f64::from_bits((centre + k) as u64), Class::UlpsFromVertical));
        }
    }
    let specials = [
        0.0,
        f64::MAX,
        f64::MIN_POSITIVE,
        f64::from_bits(1),
        f64::from_bits((1 << 52) - 1),
        f64::EPSILON,
        1.0,
        1.0 + f64::EPSILON,
        1.0 - f64::EPSILON / 2.0,
        9007199254740992.0,
        9007199254740993.0,
        9223372036854775808.0,
        1e16,
        1e22,
        1e23,
        0.1,
        0.2,
        0.3,
        1.0 / 3.0,
        2.0 / 3.0,
        std::f64::consts::PI,
        FRAC_PI_2,
        1.5707962967948965,
        9.81,
        1e-300,
        1e300,
        2.225073858507201e-308,
    ];
    for x in specials {
        values.push((x, Class::Special));
        values.push((-x, Class::Special));
    }
    values
}

/// The random doubles, each in the three forms: listed values first, then draws.
fn doubles() -> Vec<Number> {
    let mut rng = Random(0x5EED_F00D);
    let mut values = listed();
    while values.len() < VALUES {
        let class = match rng.below(10) {
            0..=4 => Class::AnyExponent,
            5 | 6 => Class::Subnormal,
            _ => Class::NearVertical,
        };
        values.push((double(&mut rng, class), class));
    }
    let mut numbers = Vec::with_capacity(3 * VALUES);
    for (x, class) in values {
        let (debug, display) = (format!("{x:?}"), format!("{x}"));
        // `{}` is `{:?}` for most values; where it is the same text it is read once.
        let display = (display != debug).then_some((Form::Display, display));
        let forms = [Some((Form::Debug, debug)), display];
        let forms = forms
            .into_iter()
            .flatten()
            .chain([(Form::Digits17, format!("{x:.16e}"))]);
        for (form, text) in forms {
            numbers.push(Number {
                expected: x,
                text,
                class,
                form,
            });
        }
    }
    numbers
}

/// The exact decimal value of a finite double, as digits `d₀d₁d₂…` and the power of ten of
/// `d₀`. Rust prints a double exactly when asked for enough digits (at most 767 are nonzero).
fn exact_decimal(x: f64) -> (Vec<u8>, i32) {
    let text = format!("{:.800e}", x.abs());
    let (mantissa, exponent) = text.split_once('e').expect("scientific notation");
    let digits = mantissa
        .bytes()
        .filter(u8::is_ascii_digit)
        .map(|d| d - b'0');
    (digits.collect(), exponent.parse().expect("an exponent"))
}

/// The decimal exactly halfway between the positive doubles `a < b`: (a + b)/2, digit by digit.
fn midpoint(a: f64, b: f64) -> (Vec<u8>, i32) {
    let (mut da, ea) = exact_decimal(a);
    let (mut db, eb) = exact_decimal(b);
    // Align to the larger exponent; the digits dropped at the end are zeros.
    let exponent = ea.max(eb);
    for (digits, e) in [(&mut da, ea), (&mut db, eb)] {
        for _ in e..exponent {
            digits.insert(0, 0);
            digits.pop();
        }
    }
    // The sum, one more digit in front.
    let mut sum = vec![0u8; da.len() + 1];
    let mut carry = 0;
    for i in (0..da.len()).rev() {
        let s = da[i] + db[i] + carry;
        sum[i + 1] = s % 10;
        carry = s / 10;
    }
    sum[0] = carry;
    // Halve it, from the front; a remainder at the end is one more digit, 5.
    let mut half = Vec::with_capacity(sum.len() + 1);
    let mut remainder = 0;
    for d in sum {
        let v = remainder * 10 + d;
        half.push(v / 2);
        remainder = v % 2;
    }
    if remainder == 1 {
        half.push(5);
    }
    // The sum's extra front digit: the midpoint's exponent is one above `exponent` if it is
    // nonzero, else drop it.
    let mut e = exponent + 1;
    while half.first() == Some(&0) {
        half.remove(0);
        e -= 1;
    }
    while half.last() == Some(&0) {
        half.pop();
    }
    (half, e)
}

fn scientific(negative: bool, digits: &[u8], exponent: i32) -> String {
    let mut text = String::with_capacity(digits.len() + 8);
    if negative {
        text.push('-');
    }
    text.push((b'0' + digits[0]) as char);
    if digits.len() > 1 {
        text.push('.');
        text.extend(digits[1..].iter().map(|d| (b'0' + d) as char));
    }
    write!(text, "e{exponent}").unwrap();
    text
}

/// Decimals at a halfway point between two neighbouring doubles (ties to even), cut short
/// (towards zero) and with a 1 twenty digits behind (away from zero): the inputs that a
/// best-effort parser gets wrong most often.
fn ties() -> Vec<Number> {
    let mut rng = Random(0x71E5);
    let mut numbers = Vec::with_capacity(3 * TIES);
    while numbers.len() < 3 * TIES {
        let class = match rng.below(4) {
            0 | 1 => Class::AnyExponent,
            2 => Class::Subnormal,
            _ => Class::NearVertical,
        };
        let a = double(&mut rng, class).abs();
        let b = f64::from_bits(a.to_bits() + 1);
        if !b.is_finite() || a == 0.0 {
            continue;
        }
        let negative = rng.next() & 1 == 0;
        let sign = if negative { -1.0 } else { 1.0 };
        let even = if a.to_bits().is_multiple_of(2) { a } else { b };
        let (digits, exponent) = midpoint(a, b);
        // Cut after the first digit where the midpoint and a differ, but before its last
        // (nonzero) digit: strictly between them.
        let (mut lower, lower_exponent) = exact_decimal(a);
        for _ in lower_exponent..exponent {
            lower.insert(0, 0);
        }
        let differ = (0..digits.len())
            .find(|&i| lower.get(i).copied().unwrap_or(0) != digits[i])
            .expect("the midpoint is above a");
        if differ + 2 > digits.len() {
            continue;
        }
        let cut = differ + 1 + rng.below((digits.len() - differ - 1) as u64) as usize;
        let below = &digits[..cut];
        let mut above = digits.clone();
        above.extend(std::iter::repeat_n(0, 19));
        above.push(1);
        for (class, digits, expected) in [
            (Class::Tie, &digits[..], even),
            (Class::BelowTie, below, a),
            (Class::AboveTie, &above[..], b),
        ] {
            let text = scientific(negative, digits, exponent);
            let expected = sign * expected;
            // The construction is right: the standard library reads it so.
            assert_eq!(
                text.parse::<f64>().unwrap().to_bits(),
                expected.to_bits(),
                "{text}"
            );
            numbers.push(Number {
                expected,
                text,
                class,
                form: Form::Long,
            });
        }
    }
    numbers
}

/// Every number a path is to read, shuffled, so that each file and each slot mixes classes
/// and forms; made once for all the tests.
fn numbers() -> &'static [Number] {
    static NUMBERS: LazyLock<Vec<Number>> = LazyLock::new(shuffled);
    &NUMBERS
}

fn shuffled() -> Vec<Number> {
    let mut all = doubles();
    all.extend(ties());
    let mut rng = Random(0x5AFF1E);
    for i in (1..all.len()).rev() {
        all.swap(i, rng.below(i as u64 + 1) as usize);
    }
    all
}

/// Wrong readings by class and form, and the first few, for the report.
#[derive(Default)]
struct Tally {
    read: BTreeMap<(Class, Form), (usize, usize)>,
    refused: usize,
    examples: Vec<String>,
}

impl Tally {
    fn check(&mut self, number: &Number, got: Result<f64, String>) {
        let entry = self.read.entry((number.class, number.form)).or_default();
        entry.0 += 1;
        let wrong = match &got {
            Ok(x) => x.to_bits() != number.expected.to_bits(),
            Err(_) => {
                self.refused += 1;
                true
            }
        };
        if wrong {
            entry.1 += 1;
            if self.examples.len() < 5 {
                self.examples.push(format!(
                    "{} read as {got:?}, not {:?}",
                    number.text, number.expected
                ));
            }
        }
    }

    /// Prints the table and fails if anything was read wrong.
    fn finish(self, path: &str) {
        let total: usize = self.read.values().map(|(n, _)| n).sum();
        let wrong: usize = self.read.values().map(|(_, w)| w).sum();
        let refused = self.refused;
        println!("{path}: {wrong} of {total} read wrong ({refused} of them refused)");
        for ((class, form), (n, w)) in &self.read {
            println!("  {class:?} {form:?}: {w} of {n}");
        }
        for example in &self.examples {
            println!("  e.g. {example}");
        }
        assert_eq!(wrong, 0, "{path}: {wrong} of {total} numbers read wrong");
    }
}

/// What one file (or command line) of a path gave back for the numbers written into it, in
/// their order: `None` where the number was not read as itself (a zero mass).
type Read = Result<Vec<Option<f64>>, String>;

/// Reads `numbers` through a path, `per_file` at a time. Where a file is refused as a whole,
/// each of its numbers is read alone, so that the one refused is counted and not the rest.
fn check_path(path: &str, numbers: &[&Number], per_file: usize, read: impl Fn(&[&Number]) -> Read) {
    let mut tally = Tally::default();
    let tally_all = |tally: &mut Tally, chunk: &[&Number], values: Vec<Option<f64>>| {
        assert_eq!(values.len(), chunk.len(), "{path}: one value per number");
        for (number, got) in chunk.iter().zip(values) {
            if let Some(got) = got {
                tally.check(number, Ok(got));
            }
        }
    };
    for chunk in numbers.chunks(per_file) {
        match read(chunk) {
            Ok(values) => tally_all(&mut tally, chunk, values),
            Err(_) => {
                for number in chunk {
                    match read(&[number]) {
                        Ok(values) => tally_all(&mut tally, &[number], values),
                        Err(error) => tally.check(number, Err(error)),
                    }
                }
            }
        }
    }
    tally.finish(path);
}

/// The texts of `numbers`, padded with `fill` to a multiple of `slots`.
fn texts<'a>(numbers: &[&'a Number], slots: usize, fill: &'a str) -> Vec<&'a str> {
    let mut texts: Vec<&str> = numbers.iter().map(|n| n.text.as_str()).collect();
    texts.resize(numbers.len().div_ceil(slots) * slots, fill);
    texts
}

/// What TOML reads as the number meant: `{}` writes a whole double without a point, which
/// TOML reads as an integer, refused beyond i64 and without the sign of −0; a scene or body
/// file holds such a value as `{:?}` or `{:.16e}` (as a person writes it too).
fn toml_accepts(number: &Number) -> bool {
    let x = number.expected;
    number.form != Form::Display || x != 0.0 && (x.fract() != 0.0 || x.abs() < 9.2e18)
}

fn toml_numbers() -> Vec<&'static Number> {
    numbers().iter().filter(|n| toml_accepts(n)).collect()
}

/// One `eom eval --model spatial` input holding 25 numbers, in the order of the fields.
fn spatial_json(s: &[&str]) -> String {
    format!(
        r#"{{"mass": {}, "inertia": [[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]],
  "state": {{"u": {}, "v": {}, "w": {}, "p": {}, "q": {}, "r": {}, "phi": {}, "theta": {}, "psi": {}}},
  "force": [{}, {}, {}], "moment": [{}, {}, {}]}}"#,
        s[0],
        s[1],
        s[2],
        s[3],
        s[4],
        s[5],
        s[6],
        s[7],
        s[8],
        s[9],
        s[10],
        s[11],
        s[12],
        s[13],
        s[14],
        s[15],
        s[16],
        s[17],
        s[18],
        s[19],
        s[20],
        s[21],
        s[22],
        s[23],
        s[24],
    )
}

#[test]
fn eval_json_reads_every_number_exactly() {
    let numbers: Vec<&Number> = numbers().iter().collect();
    // The deserialisation `eom eval` runs, on inputs of 25 numbers each.
    check_path("eom eval JSON", &numbers, 25, |chunk| {
        let text = spatial_json(&texts(chunk, 25, "0"));
        let input: SpatialInput = parse(&text).map_err(|e| e.to_string())?;
        let t = &input.state;
        let mut read = vec![input.mass];
        read.extend(input.inertia.iter().flatten());
        read.extend([t.u, t.v, t.w, t.p, t.q, t.r, t.phi, t.theta, t.psi]);
        read.extend(input.force.iter().chain(&input.moment));
        Ok(read.into_iter().take(chunk.len()).map(Some).collect())
    });
}

/// A spatial scene whose initial velocity, rates and position are the nine numbers given.
fn scene_text(nine: &[&str]) -> String {
    format!(
        "title = \"t\"\n\
         [body]\nmass = 1.0\ninertia = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.0]]\n\
         [model]\nfamily = \"spatial\"\nkinematics = \"euler\"\n\
         [initial]\nvelocity = [{}, {}, {}]\nrates = [{}, {}, {}]\nposition = [{}, {}, {}]\n\
         [integrator]\nmethod = \"rk4\"\nstep = 0.1\nend_time = 1.0\n",
        nine[0], nine[1], nine[2], nine[3], nine[4], nine[5], nine[6], nine[7], nine[8]
    )
}

#[test]
fn scene_files_read_every_number_exactly() {
    // A whole scene per nine numbers, checked as `eom run` checks it; the state starts
    // [u, v, w, p, q, r, x, y, z] as written.
    check_path("scene (BodyScene::parse)", &toml_numbers(), 9, |chunk| {
        let text = scene_text(&texts(chunk, 9, "0.0"));
        let scene =
            BodyScene::parse(&text, "exact.toml", Path::new(".")).map_err(|e| e.to_string())?;
        Ok(scene.initial[..chunk.len()]
            .iter()
            .copied()
            .map(Some)
            .collect())
    });
}

/// Numbers read through a sweep: the same TOML reader as a scene file, but each case is a
/// scene of its own, so a sample is enough.
const SWEPT: usize = 30_000;

#[test]
fn scene_sweeps_read_every_number_exactly() {
    // One sweep of 1000 positions per file: each case's position is three of the numbers.
    check_path(
        "scene sweep (sweep::cases)",
        &toml_numbers()[..SWEPT],
        3000,
        |chunk| {
            let mut text = scene_text(&["0.0"; 9]);
            text.push_str("[sweep]\n\"initial.position\" = [\n");
            for xyz in texts(chunk, 3, "0.0").chunks(3) {
                writeln!(text, "  [{}, {}, {}],", xyz[0], xyz[1], xyz[2]).unwrap();
            }
            text.push_str("]\n");
            let mut read = Vec::new();
            for case in sweep::cases(&text, "exact.toml").map_err(|e| e.to_string())? {
                let scene = BodyScene::from_table(case.table, "exact.toml", Path::new("."))
                    .map_err(|e| e.to_string())?;
                read.extend(scene.initial[6..9].iter().copied().map(Some));
            }
            read.truncate(chunk.len());
            Ok(read)
        },
    );
}

#[test]
fn body_files_read_every_number_exactly() {
    // Point masses, 2000 per file: the mass is a number's magnitude (a mass is positive, and
    // a zero is left out), the offset three more numbers as they are.
    check_path(
        "body file (BodyFile::parse)",
        &toml_numbers(),
        8000,
        |chunk| {
            let mut text = String::new();
            let slots = texts(chunk, 4, "0.0");
            for four in slots.chunks(4) {
                let mass = four[0].trim_start_matches('-');
                let mass = if mass.parse::<f64>() == Ok(0.0) {
                    "1.0"
                } else {
                    mass
                };
                writeln!(
                    text,
                    "[[part]]\nkind = \"point\"\nmass = {mass}\noffset = [{}, {}, {}]",
                    four[1], four[2], four[3]
                )
                .unwrap();
            }
            let body = BodyFile::parse(&text, Path::new(".")).map_err(|e| e.to_string())?;
            let mut read = Vec::new();
            for (four, part) in slots.chunks(4).zip(body.parts()) {
                // The mass given the sign written, so that it compares with the number.
                let mass = match four[0] {
                    m if m.parse::<f64>() == Ok(0.0) => None,
                    m if m.starts_with('-') => Some(-part.mass),
                    _ => Some(part.mass),
                };
                read.push(mass);
                read.extend(part.centre_of_gravity.iter().copied().map(Some));
            }
            read.truncate(chunk.len());
            Ok(read)
        },
    );
}

/// The four faces of the tetrahedron (a, b, c, d), each edge once in each direction, so that
/// the vertices first appear in the order a, b, c, d.
const FACES: [[usize; 3]; 4] = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];

#[test]
fn ascii_stl_meshes_read_every_number_exactly() {
    // Closed tetrahedra, one shell each (a file may hold several shells), 1200 coordinates
    // per file. Two vertices at the same point would be merged into one; random numbers
    // never make one, and the padding of the last tetrahedron is distinct integers.
    let numbers: Vec<&Number> = numbers().iter().collect();
    check_path("ASCII STL (Mesh::read_stl)", &numbers, 1200, |chunk| {
        let padding: Vec<String> = (chunk.len()..chunk.len().div_ceil(12) * 12)
            .map(|k| format!("{}", 1000 + k))
            .collect();
        let coordinates: Vec<&str> = chunk
            .iter()
            .map(|n| n.text.as_str())
            .chain(padding.iter().map(String::as_str))
            .collect();
        let mut text = String::from("solid exact\n");
        for tetrahedron in coordinates.chunks(12) {
            for face in FACES {
                text.push_str("  facet normal 0 0 0\n    outer loop\n");
                for v in face {
                    let [x, y, z] = [0, 1, 2].map(|k| tetrahedron[3 * v + k]);
                    writeln!(text, "      vertex {x} {y} {z}").unwrap();
                }
                text.push_str("    endloop\n  endfacet\n");
            }
        }
        text.push_str("endsolid exact\n");
        let mesh = Mesh::read_stl(&mut std::io::Cursor::new(text.as_bytes()))
            .map_err(|e| e.to_string())?;
        assert_eq!(
            3 * mesh.vertices().len(),
            coordinates.len(),
            "vertices merged"
        );
        let read = mesh.vertices().iter().flat_map(|v| v.iter().copied());
        Ok(read.take(chunk.len()).map(Some).collect())
    });
}

#[test]
fn binary_stl_meshes_keep_every_f32_coordinate() {
    // A binary STL stores f32; read into f64 each must be the same number.
    let mut rng = Random(0xB1A);
    let coordinates: Vec<f32> = std::iter::from_fn(|| Some(f32::from_bits(rng.next() as u32)))
        .filter(|x| x.is_finite())
        .take(12 * 2000)
        .collect();
    let triangles = coordinates.len() / 12 * FACES.len();
    let mut bytes = vec![0u8; 80];
    bytes.extend((triangles as u32).to_le_bytes());
    for tetrahedron in coordinates.chunks_exact(12) {
        for face in FACES {
            bytes.extend([0u8; 12]);
            for i in face {
                for x in &tetrahedron[3 * i..3 * i + 3] {
                    bytes.extend(x.to_le_bytes());
                }
            }
            bytes.extend([0u8; 2]);
        }
    }
    let mesh = Mesh::read_stl(&mut std::io::Cursor::new(bytes)).unwrap();
    let read: Vec<f64> = mesh
        .vertices()
        .iter()
        .flat_map(|v| v.iter().copied())
        .collect();
    let expected: Vec<f64> = coordinates.iter().map(|&x| f64::from(x)).collect();
    assert_eq!(read.len(), expected.len());
    for (got, want) in read.iter().zip(&expected) {
        assert_eq!(got.to_bits(), want.to_bits(), "{got:?} vs {want:?}");
    }
}

#[test]
fn command_line_numbers_read_every_number_exactly() {
    // The flags are clap's f64 values (`eom swing --period`, `eom tradeoff --target`, …), read
    // with `f64::from_str`; `eom mass --about x,y,z` splits and reads with the same. Here
    // 5000 values per command line (`--value=…`, each) through clap's own f64 parser.
    let numbers: Vec<&Number> = numbers().iter().collect();
    check_path(
        "command line (clap, f64::from_str)",
        &numbers,
        5000,
        |chunk| {
            let command = clap::Command::new("eom").arg(
                clap::Arg::new("value")
                    .long("value")
                    .action(clap::ArgAction::Append)
                    .allow_negative_numbers(true)
                    .value_parser(clap::value_parser!(f64)),
            );
            let args = chunk.iter().map(|n| format!("--value={}", n.text));
            let matches = command
                .try_get_matches_from(std::iter::once("eom".to_owned()).chain(args))
                .map_err(|e| e.to_string())?;
            let read = matches.get_many::<f64>("value").expect("values");
            Ok(read.copied().map(Some).collect())
        },
    );
}

/// Runs the `eom` binary and parses its JSON output.
fn eom_json(args: &[&str]) -> serde_json::Value {
    let output = eom_command()
        .args(args)
        .current_dir(root())
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).unwrap()
}

#[test]
fn the_binary_echoes_its_flags_exactly() {
    // A few real runs: `eom swing` echoes its flags, `eom mass` its --about point, each
    // printed by serde_json in its shortest exact form.
    let mut rng = Random(0xC11);
    for _ in 0..4 {
        let mut near = |x: f64| x * (1.0 + 0.01 * (rng.unit() - 0.5));
        let [period, h, mass, amplitude] = [1.45, 0.12, 20.0, 15.0].map(&mut near);
        let (p, hh, m, a) = (
            format!("{period:.16e}"),
            format!("{h:?}"),
            format!("{mass:.16e}"),
            format!("{amplitude}"),
        );
        let report = eom_json(&[
            "swing",
            "--json",
            "--period",
            &p,
            "--pivot-to-cg",
            &hh,
            "--mass",
            &m,
            "--amplitude-deg",
            &a,
        ]);
        for (key, x) in [
            ("period", period),
            ("pivot_to_cg", h),
            ("mass", mass),
            ("amplitude_deg", amplitude),
        ] {
            assert_eq!(
                report[key].as_f64().unwrap().to_bits(),
                x.to_bits(),
                "{key}"
            );
        }
    }
    for _ in 0..4 {
        let point = [0, 1, 2].map(|_| rng.sign() * 10f64.powf(-6.0 + 8.0 * rng.unit()));
        let about = format!("{:.16e},{:?},{}", point[0], point[1], point[2]);
        let report = eom_json(&[
            "mass",
            "scenes/bodies/ship_blocks.toml",
            "--json",
            "--about",
            &about,
        ]);
        for (k, x) in point.iter().enumerate() {
            let got = report["about"]["point"][k].as_f64().unwrap();
            assert_eq!(got.to_bits(), x.to_bits(), "{about}");
        }
    }
}
