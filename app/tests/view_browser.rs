//! `view.html` in a real browser: the default scene's view opened in headless Chromium at
//! several times, the page's own account of what it drew (`<pre id="probe">`, with
//! `--dump-dom`) checked against the trajectory, and a screenshot checked against that
//! account: the box's corners are where trajectory.csv's attitude puts the box of the scene's
//! mass and moments, each face turned to the camera faces the way its principal axis points,
//! and the face's colour is in the screenshot where the camera projects the face's centre.
//! The page must log nothing (Chromium prints a page's console on its standard error).
//!
//! Where Chromium is absent (`/usr/bin/chromium`, or the path in `EOM_CHROMIUM`), the browser
//! test says so on standard error and passes: CI installs it (`.ci/run`), so it runs there.

use eom::nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use eom_test_support::cli::{eom_command, folder, root};
use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The browser window, CSS pixels, one device pixel each.
const WINDOW: (u32, u32) = (1000, 700);

/// The times of the default scene looked at: the start, during the first flip, between
/// flips, and late.
const TIMES: [f64; 4] = [0.0, 2.65, 5.3, 13.07];

fn chromium() -> Option<PathBuf> {
    let path = std::env::var_os("EOM_CHROMIUM")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("/usr/bin/chromium"));
    path.exists().then_some(path)
}

fn run_eom(scene: &Path, out: &Path) {
    let output = eom_command()
        .args([
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// What a browser run printed.
struct Printed {
    stdout: String,
    stderr: String,
}

/// Runs headless Chromium on `url` with `extra` arguments, a fresh profile each time, and
/// kills it after a minute. Its output goes to files (a page dumped is larger than a pipe
/// holds, and a pipe not read while waiting would stall it).
fn browse(chromium: &Path, profile: &Path, url: &str, extra: &[&str]) -> Printed {
    let _ = std::fs::remove_dir_all(profile);
    std::fs::create_dir_all(profile).unwrap();
    let (out_path, err_path) = (profile.join("stdout.txt"), profile.join("stderr.txt"));
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
            "--force-device-scale-factor=1",
            "--enable-logging=stderr",
            "--v=0",
            "--virtual-time-budget=5000",
        ])
        .arg(format!(
            "--user-data-dir={}",
            profile.join("data").display()
        ))
        .arg(format!("--window-size={},{}", WINDOW.0, WINDOW.1))
        .args(extra)
        .arg(url)
        .stdout(Stdio::from(File::create(&out_path).unwrap()))
        .stderr(Stdio::from(File::create(&err_path).unwrap()))
        .spawn()
        .unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("Chromium took more than a minute on {url}");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    Printed {
        stdout: std::fs::read_to_string(out_path).unwrap(),
        stderr: std::fs::read_to_string(err_path).unwrap(),
    }
}

/// What the page logged to its console: Chromium writes each message as a `CONSOLE` line.
fn console_lines(output: &Printed) -> Vec<String> {
    output
        .stderr
        .lines()
        .filter(|l| l.contains("CONSOLE"))
        .map(String::from)
        .collect()
}

/// The JSON in the dumped page's `<pre id="probe">`.
fn probe_of(dom: &str) -> serde_json::Value {
    let start = dom
        .find("<pre id=\"probe\">")
        .expect("no probe in the page")
        + 16;
    let end = start + dom[start..].find("</pre>").unwrap();
    let text = dom[start..end]
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&");
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("probe is not JSON: {e}: {text}"))
}

fn vector(v: &serde_json::Value) -> Vector3<f64> {
    Vector3::new(
        v[0].as_f64().unwrap(),
        v[1].as_f64().unwrap(),
        v[2].as_f64().unwrap(),
    )
}

/// The row of trajectory.csv at time `t` (the rows fall on t = k·every).
fn row_at(out: &Path, t: f64) -> (Vec<String>, Vec<f64>) {
    let text = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines
        .next()
        .unwrap()
        .split(',')
        .map(|h| h.split('[').next().unwrap().to_string())
        .collect();
    let row = lines
        .map(|l| {
            l.split(',')
                .map(|x| x.parse::<f64>().unwrap())
                .collect::<Vec<_>>()
        })
        .min_by(|a, b| (a[0] - t).abs().total_cmp(&(b[0] - t).abs()))
        .unwrap();
    (header, row)
}

/// The scene's mass and principal moments (its tensor is diagonal).
fn mass_and_moments(scene: &Path) -> (f64, [f64; 3]) {
    let table: toml::Table = std::fs::read_to_string(scene).unwrap().parse().unwrap();
    let body = table["body"].as_table().unwrap();
    let mass = body["mass"].as_float().unwrap();
    let inertia = body["inertia"].as_array().unwrap();
    let moments = [0, 1, 2].map(|k| inertia[k].as_array().unwrap()[k].as_float().unwrap());
    (mass, moments)
}

/// The corners of the uniform box of `mass` and `moments` turned by `rotation`: its sides
/// from 4.20–4.21, I₁ = M(b² + c²)/12 and its cycles.
fn box_corners(mass: f64, moments: [f64; 3], rotation: &Matrix3<f64>) -> Vec<Vector3<f64>> {
    let [i1, i2, i3] = moments;
    let half = [i2 + i3 - i1, i1 + i3 - i2, i1 + i2 - i3].map(|s| (6.0 * s / mass).sqrt() / 2.0);
    let mut corners = Vec::new();
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            for sz in [-1.0, 1.0] {
                let body = Vector3::new(sx * half[0], sy * half[1], sz * half[2]);
                corners.push(rotation * body);
            }
        }
    }
    corners
}

/// A point in the page's drawing axes to CSS pixels, by the camera the page reports.
fn project(camera: &serde_json::Value, p: &Vector3<f64>) -> (f64, f64) {
    let eye = vector(&camera["eye"]);
    let (r, u, f) = (
        vector(&camera["right"]),
        vector(&camera["up"]),
        vector(&camera["forward"]),
    );
    let focal = camera["focal"].as_f64().unwrap();
    let centre = &camera["centre"];
    let d = p - eye;
    let z = d.dot(&f);
    (
        centre[0].as_f64().unwrap() + focal * d.dot(&r) / z,
        centre[1].as_f64().unwrap() - focal * d.dot(&u) / z,
    )
}

/// The screenshot's pixels, RGB(A), with its width.
struct Picture {
    width: usize,
    height: usize,
    channels: usize,
    pixels: Vec<u8>,
}

impl Picture {
    fn read(path: &Path) -> Picture {
        let decoder = png::Decoder::new(std::fs::File::open(path).unwrap());
        let mut reader = decoder.read_info().unwrap();
        let mut pixels = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut pixels).unwrap();
        assert_eq!(info.bit_depth, png::BitDepth::Eight);
        let channels = info.color_type.samples();
        Picture {
            width: info.width as usize,
            height: info.height as usize,
            channels,
            pixels,
        }
    }

    fn at(&self, x: usize, y: usize) -> [u8; 3] {
        let i = (y * self.width + x) * self.channels;
        [self.pixels[i], self.pixels[i + 1], self.pixels[i + 2]]
    }

    /// The share of the 5 × 5 pixels around (x, y) within `tolerance` of `colour` in every
    /// channel.
    fn share_near(&self, (x, y): (f64, f64), colour: [u8; 3], tolerance: u8) -> f64 {
        let (x, y) = (x.round() as i64, y.round() as i64);
        let mut hits = 0;
        for dy in -2..=2 {
            for dx in -2..=2 {
                let pixel = self.at((x + dx) as usize, (y + dy) as usize);
                if pixel
                    .iter()
                    .zip(colour)
                    .all(|(a, b)| a.abs_diff(b) <= tolerance)
                {
                    hits += 1;
                }
            }
        }
        f64::from(hits) / 25.0
    }
}

fn inside(rect: &serde_json::Value, (x, y): (f64, f64), margin: f64) -> bool {
    let r = |k: usize| rect[k].as_f64().unwrap();
    x > r(0) - margin && x < r(2) + margin && y > r(1) - margin && y < r(3) + margin
}

#[test]
fn the_default_scene_s_view_draws_the_trajectory_in_chromium() {
    let Some(chromium) = chromium() else {
        eprintln!(
            "\n*** view_browser: NO CHROMIUM at /usr/bin/chromium (or EOM_CHROMIUM): the browser \
             test of view.html did NOT run. Install Debian's chromium (CI's .ci/run does) to run \
             it. ***\n"
        );
        return;
    };
    let out = folder("tennis_racket");
    let scene = root().join("scenes/tennis_racket.toml");
    run_eom(&scene, &out);
    let view = out.join("view.html");
    let size = std::fs::metadata(&view).unwrap().len();
    println!("view.html of the default scene: {size} bytes");
    let (mass, moments) = mass_and_moments(&scene);
    let profile = out.join("profile");
    let mut faces_checked = 0;
    for t in TIMES {
        let url = format!(
            "file://{}#t={t}&size={}x{}&probe",
            view.display(),
            WINDOW.0,
            WINDOW.1
        );
        let dumped = browse(&chromium, &profile, &url, &["--dump-dom"]);
        let console = console_lines(&dumped);
        assert!(console.is_empty(), "t = {t}: the page logged {console:?}");
        let probe = probe_of(&dumped.stdout);
        assert_eq!(probe["errors"].as_array().unwrap().len(), 0, "{probe}");
        assert_eq!(probe["size"], serde_json::json!([WINDOW.0, WINDOW.1]));

        // The frame shown is the row at t, and the box is where its attitude puts it.
        let (header, row) = row_at(&out, t);
        let shown = probe["t"].as_f64().unwrap();
        assert!((shown - row[0]).abs() < 1e-5, "t = {t}: page at {shown}");
        let q = |name: &str| row[header.iter().position(|h| h == name).unwrap()];
        let attitude =
            UnitQuaternion::from_quaternion(Quaternion::new(q("q0"), q("q1"), q("q2"), q("q3")));
        let rotation = *attitude.to_rotation_matrix().matrix();
        let position = Vector3::new(q("x"), q("y"), q("z"));
        let expected: Vec<Vector3<f64>> = box_corners(mass, moments, &rotation)
            .into_iter()
            .map(|c| c + position)
            .collect();
        let drawn: Vec<Vector3<f64>> = probe["corners"]
            .as_array()
            .unwrap()
            .iter()
            .map(vector)
            .collect();
        assert_eq!(drawn.len(), 8);
        for corner in &expected {
            let nearest = drawn
                .iter()
                .map(|d| (d - corner).norm())
                .fold(f64::INFINITY, f64::min);
            assert!(
                nearest < 1e-5,
                "t = {t}: no corner drawn at {corner:?}: {drawn:?}"
            );
        }

        // Space axes are z down; the page draws with z up, turned half a turn about x.
        let to_draw = Matrix3::from_fn(|r, c| probe["toDraw"][r][c].as_f64().unwrap());
        assert_eq!(
            to_draw,
            Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, -1.0))
        );
        let camera = &probe["camera"];
        let eye = vector(&camera["eye"]);

        let shot = out.join(format!("t{t}.png"));
        let url = format!(
            "file://{}#t={t}&size={}x{}",
            view.display(),
            WINDOW.0,
            WINDOW.1
        );
        let taken = browse(
            &chromium,
            &profile,
            &url,
            &[&format!("--screenshot={}", shot.display())],
        );
        assert!(console_lines(&taken).is_empty(), "t = {t}: the page logged");
        let picture = Picture::read(&shot);
        assert_eq!((picture.width, picture.height), (1000, 700));

        for face in probe["faces"].as_array().unwrap() {
            let name = face["name"].as_str().unwrap();
            // The face's centre, from the corners the trajectory gives.
            let corners: Vec<Vector3<f64>> = face["corners"]
                .as_array()
                .unwrap()
                .iter()
                .map(|k| drawn[k.as_u64().unwrap() as usize])
                .collect();
            let centre_space = corners.iter().sum::<Vector3<f64>>() / 4.0;
            // It faces the way its principal axis (here body axis) points, by the attitude.
            let axis: usize = name[1..].parse::<usize>().unwrap() - 1;
            let sign = if name.starts_with('+') { 1.0 } else { -1.0 };
            let outward = rotation.column(axis) * sign;
            let normal = to_draw.transpose() * vector(&face["normal"]);
            assert!(
                (normal - outward).norm() < 1e-4,
                "t = {t}: face {name} faces {normal:?}, the attitude says {outward:?}"
            );
            let centre = to_draw * centre_space;
            // Only faces turned well towards the camera, large on the screen and clear of
            // the panels, are looked for in the picture.
            let towards = (eye - centre).normalize().dot(&(to_draw * outward));
            let outline: Vec<(f64, f64)> = corners
                .iter()
                .map(|c| project(camera, &(to_draw * c)))
                .collect();
            let area = shoelace(&outline).abs();
            let at = project(camera, &centre);
            let reported = face["screen"].as_array().unwrap();
            let mean = reported.iter().fold((0.0, 0.0), |(x, y), p| {
                (
                    x + p[0].as_f64().unwrap() / 4.0,
                    y + p[1].as_f64().unwrap() / 4.0,
                )
            });
            let outline_mean = outline
                .iter()
                .fold((0.0, 0.0), |(x, y), p| (x + p.0 / 4.0, y + p.1 / 4.0));
            assert!(
                (mean.0 - outline_mean.0).hypot(mean.1 - outline_mean.1) < 0.5,
                "t = {t}: face {name} drawn at {mean:?}, projected at {outline_mean:?}"
            );
            let hidden = probe["panels"]
                .as_array()
                .unwrap()
                .iter()
                .any(|rect| inside(rect, at, 4.0));
            if towards < 0.3 || area < 2000.0 || hidden {
                continue;
            }
            let fill = face["fill"].as_array().unwrap();
            let fill = [0, 1, 2].map(|k| fill[k].as_u64().unwrap() as u8);
            // The face's hue is its axis's: red, green, blue for the first, second, third.
            let strongest = (0..3).max_by_key(|&k| fill[k]).unwrap();
            assert_eq!(strongest, axis, "t = {t}: face {name} is {fill:?}");
            // Four points between the centre and the corners: the body axis through the
            // centre, and a line drawn over the face, cover at most one of them.
            let shares: Vec<f64> = outline
                .iter()
                .map(|c| (at.0 + 0.45 * (c.0 - at.0), at.1 + 0.45 * (c.1 - at.1)))
                .map(|p| picture.share_near(p, fill, 12))
                .collect();
            let found = shares.iter().filter(|s| **s >= 0.6).count();
            assert!(
                found >= 3,
                "t = {t}: face {name} ({fill:?}) should be around {at:?} in {}: the share of \
                 its colour near four points is {shares:?}",
                shot.display(),
            );
            faces_checked += 1;
        }
    }
    println!("faces found in the screenshots where the attitude puts them: {faces_checked}");
    assert!(
        faces_checked >= TIMES.len(),
        "{faces_checked} faces checked"
    );
}

/// Twice the signed area of a polygon.
fn shoelace(points: &[(f64, f64)]) -> f64 {
    let n = points.len();
    (0..n)
        .map(|k| {
            let (a, b) = (points[k], points[(k + 1) % n]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum::<f64>()
        / 2.0
}

#[test]
fn a_ten_thousand_row_run_makes_a_view_under_two_megabytes() {
    let out = folder("ten_thousand");
    let text = std::fs::read_to_string(root().join("scenes/tennis_racket.toml")).unwrap();
    // 20 s at every 2 ms: 10 001 rows of 13 states.
    let text = text.replace("every = 0.01 ", "every = 0.002");
    assert!(text.contains("every = 0.002"));
    let scene = out.join("racket_10k.toml");
    std::fs::write(&scene, text).unwrap();
    run_eom(&scene, &out.join("run"));
    let rows = std::fs::read_to_string(out.join("run/trajectory.csv"))
        .unwrap()
        .lines()
        .count()
        - 1;
    assert_eq!(rows, 10_001);
    let size = std::fs::metadata(out.join("run/view.html")).unwrap().len();
    println!("view.html of a {rows}-row run: {size} bytes");
    assert!(size < 2_000_000, "{size} bytes");
}
