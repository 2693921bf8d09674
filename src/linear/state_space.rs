//! The linear model as control tools read it: ẋ = A x + B u, y = C x + D u about the point,
//! where x is the reduced state and u the inputs (both as deviations from the point x₀, u₀),
//! with the names and units of x, u and y, the states set aside (their values and why) and
//! how A and B were obtained.
//!
//! One definition for each output that holds it: its serialisation gives the keys of
//! `linear.json` (and of `eom linear --json`, which prints the same object), and
//! [`StateSpace::mat_variables`] the variables of `linear.mat`, of the same names. The names
//! are python-control's (`control.ss(A, B, C, D, inputs=u_names, outputs=y_names,
//! states=x_names)`) and MATLAB's `ss` takes them as they are. Every number is written so
//! that it reads back to the same double: serde_json writes the shortest decimal that does
//! (ryu), the MAT-file the eight bytes themselves.

use super::Linearisation;
use crate::output::mat::MatValue;
use nalgebra::DMatrix;
use serde::{Serialize, Serializer};

/// A linearisation as a state-space model (see the module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StateSpace {
    /// The scene file, as it was given.
    pub scene: String,
    /// The scene's title.
    pub title: String,
    /// ∂f/∂x on the reduced state.
    #[serde(rename = "A", serialize_with = "rows")]
    pub a: DMatrix<f64>,
    /// ∂f/∂u: the reduced state's rates by every input.
    #[serde(rename = "B", serialize_with = "rows")]
    pub b: DMatrix<f64>,
    /// The outputs' rows of the identity over the reduced state.
    #[serde(rename = "C", serialize_with = "rows")]
    pub c: DMatrix<f64>,
    /// Zero: the outputs are state entries.
    #[serde(rename = "D", serialize_with = "rows")]
    pub d: DMatrix<f64>,
    /// The reduced state's names, in the order of A's rows and columns.
    pub x_names: Vec<&'static str>,
    /// The inputs' names, in the order of B's columns.
    pub u_names: Vec<&'static str>,
    /// The outputs' names, in the order of C's rows.
    pub y_names: Vec<&'static str>,
    /// The units of x (`null` for a name of no known unit).
    pub x_units: Vec<Option<&'static str>>,
    /// The units of u.
    pub u_units: Vec<Option<&'static str>>,
    /// The units of y.
    pub y_units: Vec<Option<&'static str>>,
    /// The reduced state at the point.
    pub x0: Vec<f64>,
    /// The inputs at the point: what acts there plus what the `[linear]` table adds.
    pub u0: Vec<f64>,
    /// The names of the states set aside.
    pub set_aside: Vec<&'static str>,
    /// Their values at the point.
    pub set_aside_values: Vec<f64>,
    /// Why each was set aside.
    pub set_aside_why: Vec<&'static str>,
    /// How A and B were obtained.
    pub jacobians: &'static str,
}

impl StateSpace {
    /// The state-space model of `linear`, a linearisation of the scene file `scene` (as it was
    /// given) titled `title`.
    pub fn new(scene: &str, title: &str, linear: &Linearisation) -> Self {
        let x_names = linear.reduced_names();
        let y_names = linear.output_names();
        let units = |names: &[&str], input: bool| {
            names
                .iter()
                .map(|name| linear.unit(name, input))
                .collect::<Vec<_>>()
        };
        StateSpace {
            scene: scene.to_owned(),
            title: title.to_owned(),
            a: linear.a.clone(),
            b: linear.b.clone(),
            c: linear.c(),
            d: linear.d(),
            x_units: units(&x_names, false),
            u_units: units(&linear.input_names, true),
            y_units: units(&y_names, false),
            x_names,
            u_names: linear.input_names.clone(),
            y_names,
            x0: linear.reduced_state(),
            u0: linear.inputs.clone(),
            set_aside: linear.set_aside_names(),
            set_aside_values: linear.set_aside_values(),
            set_aside_why: (linear.set_aside_why.iter())
                .map(|why| why.describe())
                .collect(),
            jacobians: linear.jacobians,
        }
    }

    /// The variables of `linear.mat`, named as the JSON keys: matrices as doubles, vectors as
    /// columns, names and units as cell arrays of strings (an unknown unit the empty string),
    /// the rest as strings.
    pub fn mat_variables(&self) -> Vec<(&'static str, MatValue)> {
        let matrix = |m: &DMatrix<f64>| MatValue::Matrix(m.clone());
        let column = |v: &[f64]| MatValue::Matrix(DMatrix::from_column_slice(v.len(), 1, v));
        let texts = |v: &[&str]| MatValue::Texts(v.iter().map(|s| (*s).to_owned()).collect());
        let units = |v: &[Option<&str>]| {
            MatValue::Texts(v.iter().map(|u| u.unwrap_or("").to_owned()).collect())
        };
        let text = |s: &str| MatValue::Text(s.to_owned());
        vec![
            ("scene", text(&self.scene)),
            ("title", text(&self.title)),
            ("A", matrix(&self.a)),
            ("B", matrix(&self.b)),
            ("C", matrix(&self.c)),
            ("D", matrix(&self.d)),
            ("x_names", texts(&self.x_names)),
            ("u_names", texts(&self.u_names)),
            ("y_names", texts(&self.y_names)),
            ("x_units", units(&self.x_units)),
            ("u_units", units(&self.u_units)),
            ("y_units", units(&self.y_units)),
            ("x0", column(&self.x0)),
            ("u0", column(&self.u0)),
            ("set_aside", texts(&self.set_aside)),
            ("set_aside_values", column(&self.set_aside_values)),
            ("set_aside_why", texts(&self.set_aside_why)),
            ("jacobians", text(self.jacobians)),
        ]
    }
}

/// A matrix as JSON's array of rows.
fn rows<S: Serializer>(matrix: &DMatrix<f64>, serializer: S) -> Result<S::Ok, S::Error> {
    serializer.collect_seq(
        matrix
            .row_iter()
            .map(|row| row.iter().copied().collect::<Vec<f64>>()),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linear::LinearError;
    use crate::scene::AnyScene;

    /// A planar body pushed against its damping at 2 m/s, with the outputs `outputs`: its
    /// track and heading are set aside.
    fn hull(outputs: &[&str]) -> Result<Linearisation, LinearError> {
        let text = "title = \"b\"\n[body]\nmass = 1000.0\nizz = 2.0e5\n[model]\n\
                    family = \"planar-g\"\n[initial]\nu = 2.0\n[loads]\n\
                    force_body = [200.0, 0.0]\nlinear_damping = [100.0, 400.0, 8.0e4]\n\
                    [integrator]\nmethod = \"dop853\"\nend_time = 1.0\n";
        let outputs: Vec<String> = outputs.iter().map(|s| format!("\"{s}\"")).collect();
        let text = match outputs.is_empty() {
            true => text.to_owned(),
            false => format!("{text}[linear]\noutputs = [{}]\n", outputs.join(", ")),
        };
        let scene = AnyScene::parse(&text, "hull.toml", std::path::Path::new(".")).unwrap();
        let linearised = scene.into_kind().linear().map_err(|error| match error {
            crate::kinds::KindError::Scene(e) | crate::kinds::KindError::Run(e) => *e
                .downcast::<LinearError>()
                .expect("a linearisation's error"),
            other => panic!("{other}"),
        });
        linearised.map(|linearised| linearised.linearisation)
    }

    fn space(outputs: &[&str]) -> StateSpace {
        StateSpace::new("hull.toml", "b", &hull(outputs).unwrap())
    }

    #[test]
    fn the_json_keys_are_the_mat_variables() {
        let space = space(&[]);
        let json = serde_json::to_value(&space).unwrap();
        let mut keys: Vec<&str> = (json.as_object().unwrap().keys())
            .map(String::as_str)
            .collect();
        let mut variables: Vec<&str> = space.mat_variables().iter().map(|v| v.0).collect();
        keys.sort_unstable();
        variables.sort_unstable();
        assert_eq!(keys, variables);
    }

    #[test]
    fn by_default_every_reduced_entry_is_an_output() {
        let space = space(&[]);
        assert_eq!(space.x_names, ["u", "v", "r"]);
        assert_eq!(space.y_names, space.x_names);
        assert_eq!(space.c, DMatrix::identity(3, 3));
        assert_eq!(space.d, DMatrix::zeros(3, 3));
        assert_eq!(space.x_units, [Some("m/s"), Some("m/s"), Some("rad/s")]);
        assert_eq!(space.u_units, [Some("N"), Some("N"), Some("N m")]);
        assert_eq!(space.x0, [2.0, 0.0, 0.0]);
        // The inputs at the point: the thrust less the damping, which hold it.
        assert_eq!(space.u0, [0.0, 0.0, 0.0]);
        assert_eq!(space.set_aside, ["X", "Y", "psi"]);
        assert_eq!(space.set_aside_values, [0.0, 0.0, 0.0]);
        assert_eq!(space.set_aside_why, ["only integrates the rest"; 3]);
        assert!(space.jacobians.starts_with("emitted and proved"));
    }

    #[test]
    fn named_outputs_pick_their_rows_in_their_order() {
        // Any case, as the trajectory's columns are named: `U` is `u`.
        let space = space(&["r", "U"]);
        assert_eq!(space.y_names, ["r", "u"]);
        assert_eq!(space.y_units, [Some("rad/s"), Some("m/s")]);
        let c = DMatrix::from_row_slice(2, 3, &[0.0, 0.0, 1.0, 1.0, 0.0, 0.0]);
        assert_eq!(space.c, c);
        assert_eq!(space.d, DMatrix::zeros(2, 3));
    }

    #[test]
    fn an_output_set_aside_is_refused_with_why() {
        let error = hull(&["v", "psi"]).unwrap_err();
        let message = error.to_string();
        assert!(
            message.contains("linear.outputs[1]")
                && message.contains("`psi` is set aside")
                && message.contains("only integrates the rest")
                && message.contains("u, v, r"),
            "{message}"
        );
        assert!(error.is_scene_error());
    }
}
