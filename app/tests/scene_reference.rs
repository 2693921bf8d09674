//! The scene reference against what it describes: every template `eom new` prints runs as
//! printed and writes its units into trajectory.csv; an unknown family is a usage error that
//! lists the families; docs/scenes.md is what the reference makes; and the key table and the
//! serde schema of scene files hold the same keys, both ways: every key the table lists is
//! accepted by the reader with its example value, and every key the reader accepts is in
//! the table (found by walking the schema itself, so a key added to a table struct and not
//! to the reference fails here).

use eom::kinds::body::file::SceneFile;
use eom::kinds::ship::scene::ShipSceneFile;
use eom::kinds::vehicle::scene::VehicleSceneFile;
use eom::scene::Problem;
use eom::scene::reference::{Key, REGENERATE, Required, SceneFamily, keys_of, markdown, template};
use eom_test_support::cli::{eom, folder, root};
use eom_test_support::schema;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// Every trajectory.csv under `out`, at any depth (a ship writes one per manoeuvre).
fn trajectories(out: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(out).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            found.extend(trajectories(&path));
        } else if path.file_name().is_some_and(|n| n == "trajectory.csv") {
            found.push(path);
        }
    }
    found
}

#[test]
fn every_template_runs_as_printed_and_labels_its_columns_with_units() {
    let dir = folder("templates");
    for family in SceneFamily::all() {
        let name = family.name();
        let printed = eom(&["new", name]);
        assert!(printed.status.success(), "eom new {name}");
        let text = String::from_utf8(printed.stdout).unwrap();
        assert_eq!(text, template(family), "eom new {name} prints the template");
        let scene = dir.join(format!("{name}.toml"));
        std::fs::write(&scene, &text).unwrap();
        let out = dir.join(name);
        let ran = eom(&[
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(
            ran.status.success(),
            "eom run of `eom new {name}`: {}",
            String::from_utf8_lossy(&ran.stderr)
        );
        let files = trajectories(&out);
        assert!(!files.is_empty(), "{name} wrote no trajectory");
        for file in files {
            let csv = std::fs::read_to_string(&file).unwrap();
            let header = csv.lines().next().unwrap();
            assert!(header.starts_with("t[s],"), "{name}: {header}");
            for field in header.split(',') {
                let (column, unit) = field
                    .strip_suffix(']')
                    .and_then(|f| f.split_once('['))
                    .unwrap_or_else(|| panic!("{name}: `{field}` has no unit"));
                assert!(!column.is_empty() && !unit.is_empty(), "{name}: {field}");
            }
            assert!(
                csv.lines().count() > 2,
                "{name}: {} has no rows",
                file.display()
            );
        }
    }
}

#[test]
fn an_unknown_family_is_a_usage_error_that_lists_the_families() {
    let output = eom(&["new", "planar"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(output.stdout.is_empty());
    let stderr = String::from_utf8_lossy(&output.stderr);
    for family in SceneFamily::all() {
        assert!(
            stderr.contains(family.name()),
            "{} in {stderr}",
            family.name()
        );
    }
    let neither = eom(&["new"]);
    assert_eq!(neither.status.code(), Some(2));
}

#[test]
fn docs_scenes_md_is_what_the_reference_makes() {
    let path = root().join("docs/scenes.md");
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == markdown(),
        "docs/scenes.md is not what src/scene/reference/ makes; regenerate it with\n\n    {REGENERATE}\n"
    );
    let printed = eom(&["new", "--reference"]);
    assert_eq!(String::from_utf8(printed.stdout).unwrap(), markdown());
}

/// The template of `family` with `key` set to its example, as a TOML table, beside the keys
/// that the tables holding it require (`required with [autopilot]`), at their examples.
fn with_example(family: SceneFamily, key: &Key) -> toml::Table {
    let mut table: toml::Table = template(family).parse().unwrap();
    let set = |table: &mut toml::Table, key: &Key| {
        let example = key.example_for(family);
        let value = if key.name() == "*" {
            toml::Value::Table(example.parse().unwrap())
        } else {
            let wrapped: toml::Table = format!("value = {example}").parse().unwrap();
            wrapped["value"].clone()
        };
        schema::set(table, key.path, value);
    };
    let holders: Vec<String> = (1..key.path.split('.').count())
        .map(|n| key.path.split('.').take(n).collect::<Vec<_>>().join("."))
        .collect();
    for other in keys_of(family) {
        let needed = matches!(other.required, Required::When(when)
            if holders.iter().any(|holder| when == format!("with [{holder}]")));
        if needed {
            set(&mut table, &other);
        }
    }
    set(&mut table, key);
    table
}

#[test]
fn every_key_in_the_reference_is_read_with_its_example() {
    for family in SceneFamily::all() {
        for key in keys_of(family) {
            let table = toml::Value::Table(with_example(family, &key));
            let read = match family {
                SceneFamily::Kind("ship") => table
                    .try_into::<ShipSceneFile>()
                    .map(drop)
                    .map_err(|e| e.to_string()),
                SceneFamily::Kind("vehicle") => table
                    .try_into::<VehicleSceneFile>()
                    .map(drop)
                    .map_err(|e| e.to_string()),
                // A kind this test does not know by its file's type is read and checked as a
                // scene of it is, through the registry, so that a new kind needs no line here:
                // the key must be read (no syntax or schema error); a value check its example
                // fails beside the template's other values (an adaptive method's tolerance
                // with the template's fixed step) is the checker's, not the reference's.
                SceneFamily::Kind(other) => {
                    let kind = eom::kinds::named(other).expect("a kind the registry lists");
                    let toml::Value::Table(table) = table else {
                        unreachable!("the template's table")
                    };
                    let source = eom::kinds::Source::Table(table);
                    match (kind.read)(source, "<template>", Path::new(".")) {
                        Ok(_) => Ok(()),
                        Err(e) if matches!(e.problem, Problem::Invalid(_)) => Ok(()),
                        Err(e) => Err(e.to_string()),
                    }
                }
                SceneFamily::Catalog(_) => table
                    .try_into::<SceneFile>()
                    .map(drop)
                    .map_err(|e| e.to_string()),
            };
            assert!(
                read.is_ok(),
                "{}: {} = {}: {:?}",
                family.name(),
                key.path,
                key.example,
                read.err()
            );
        }
    }
}

/// The paths the reference gives `families`.
fn reference_paths(families: &[SceneFamily]) -> BTreeSet<String> {
    families
        .iter()
        .flat_map(|f| keys_of(*f))
        .map(|k| k.path.to_owned())
        .collect()
}

#[test]
fn every_key_the_reader_accepts_is_in_the_reference() {
    let catalog: Vec<SceneFamily> = SceneFamily::all()
        .into_iter()
        .filter(|f| matches!(f, SceneFamily::Catalog(_)))
        .collect();
    let walked = schema::keys::<SceneFile>();
    assert!(walked.contains("integrator.step") && walked.contains("sweep.*"));
    assert_eq!(walked, reference_paths(&catalog), "catalog scenes");
    let walked = schema::keys::<ShipSceneFile>();
    assert!(walked.contains("manoeuvre[].kind"));
    assert_eq!(
        walked,
        reference_paths(&[SceneFamily::Kind("ship")]),
        "ship scenes"
    );
    let walked = schema::keys::<VehicleSceneFile>();
    assert!(walked.contains("hydrodynamics.added_mass.*"));
    assert_eq!(
        walked,
        reference_paths(&[SceneFamily::Kind("vehicle")]),
        "vehicle scenes"
    );
}

#[test]
fn a_key_of_another_family_is_refused_naming_what_the_family_takes() {
    let text = template(SceneFamily::all()[0]).replace("[body]\n", "[body]\nizz = 3.0\n");
    let error = eom::scene::AnyScene::parse(&text, "<scene>", Path::new(".")).unwrap_err();
    assert_eq!(error.key, "body.izz");
    let message = error.to_string();
    for key in keys_of(SceneFamily::all()[0]).filter(|k| k.table() == "body") {
        assert!(message.contains(key.name()), "{message}");
    }
}
