//! An aircraft scene's `[aerodynamics]` keys: the tables of the Stevens & Lewis form, or a
//! textbook's stability derivatives.

use super::AIRCRAFT;
use crate::scene::reference::{Key, Kind, Required};

/// The `[aerodynamics]` keys, in the order a template writes them.
pub const AERODYNAMICS: &[Key] = &[
    Key {
        path: "aerodynamics.cx.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "C_x(α, δe), the body-x force coefficient: its α breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cx.elevator_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its elevator breakpoints, strictly increasing.",
        example: "[-12.0, 0.0, 12.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cx.values",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per α"),
        unit: "-",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its values, [α][the second argument].",
        example: "[[-0.04, -0.021, -0.039], [-0.021, -0.004, -0.025], [0.016, 0.032, 0.006]]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cz.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "C_z(α), the body-z force coefficient at zero sideslip and elevator (times 1 − (β/57.3°)², less 0.19 δe/25°): its α breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cz.values",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "-",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its values, one per α.",
        example: "[-0.1, -0.416, -0.731]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cm.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "C_m(α, δe), the pitching moment about the reference: its α breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cm.elevator_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its elevator breakpoints, strictly increasing.",
        example: "[-12.0, 0.0, 12.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cm.values",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per α"),
        unit: "-",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its values, [α][the second argument].",
        example: "[[0.107, -0.009, -0.121], [0.11, -0.005, -0.127], [0.11, -0.006, -0.129]]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cl.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "C_l(α, |β|), the rolling moment, odd in β: its α breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cl.beta_abs_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its beta (absolute) breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cl.values",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per α"),
        unit: "-",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its values, [α][the second argument].",
        example: "[[0.0, -0.008, -0.017], [0.0, -0.012, -0.024], [0.0, -0.016, -0.03]]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cn.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "C_n(α, |β|), the yawing moment about the reference, odd in β: its α breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cn.beta_abs_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its beta (absolute) breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.cn.values",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per α"),
        unit: "-",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its values, [α][the second argument].",
        example: "[[0.0, 0.018, 0.042], [0.0, 0.019, 0.042], [0.0, 0.019, 0.043]]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dlda.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "ΔC_l per unit aileron (δa/20°), in α and β: its α breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dlda.beta_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its beta breakpoints, strictly increasing.",
        example: "[-10.0, 0.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dlda.values",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per α"),
        unit: "-",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its values, [α][the second argument].",
        example: "[[-0.052, -0.051, -0.048], [-0.051, -0.052, -0.049], [-0.049, -0.048, -0.043]]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dldr.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "ΔC_l per unit rudder (δr/30°), in α and β: its α breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dldr.beta_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its beta breakpoints, strictly increasing.",
        example: "[-10.0, 0.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dldr.values",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per α"),
        unit: "-",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its values, [α][the second argument].",
        example: "[[0.011, 0.015, 0.013], [0.012, 0.014, 0.013], [0.011, 0.014, 0.012]]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dnda.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "ΔC_n per unit aileron, in α and β: its α breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dnda.beta_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its beta breakpoints, strictly increasing.",
        example: "[-10.0, 0.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dnda.values",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per α"),
        unit: "-",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its values, [α][the second argument].",
        example: "[[-0.006, -0.01, -0.014], [-0.006, -0.009, -0.012], [-0.005, -0.008, -0.011]]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dndr.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "ΔC_n per unit rudder, in α and β: its α breakpoints, strictly increasing.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dndr.beta_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its beta breakpoints, strictly increasing.",
        example: "[-10.0, 0.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.dndr.values",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per α"),
        unit: "-",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "Its values, [α][the second argument].",
        example: "[[-0.038, -0.045, -0.041], [-0.04, -0.045, -0.041], [-0.04, -0.044, -0.04]]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "deg",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "The damping derivatives' α breakpoints, strictly increasing; each derivative below is per radian of its non-dimensional rate (q c̄/2V for CXq, CZq, Cmq; p b/2V and r b/2V for the others), one value per α.",
        example: "[0.0, 5.0, 10.0]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.CXq",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "1/rad",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "∂C_x/∂(q c̄/2V), one per α.",
        example: "[0.308, 1.34, 2.08]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.CYr",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "1/rad",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "∂C_y/∂(r b/2V), one per α.",
        example: "[0.876, 0.958, 0.962]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.CYp",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "1/rad",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "∂C_y/∂(p b/2V), one per α.",
        example: "[-0.188, 0.11, 0.258]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.CZq",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "1/rad",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "∂C_z/∂(q c̄/2V), one per α.",
        example: "[-28.9, -31.4, -31.2]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.Clr",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "1/rad",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "∂C_l/∂(r b/2V), one per α.",
        example: "[0.063, 0.113, 0.208]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.Clp",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "1/rad",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "∂C_l/∂(p b/2V), one per α.",
        example: "[-0.443, -0.42, -0.383]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.Cmq",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "1/rad",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "∂C_m/∂(q c̄/2V), one per α.",
        example: "[-5.23, -5.26, -6.11]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.Cnr",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "1/rad",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "∂C_n/∂(r b/2V), one per α.",
        example: "[-0.378, -0.386, -0.37]",
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.damping.Cnp",
        families: AIRCRAFT,
        kind: Kind::Numbers("one per α"),
        unit: "1/rad",
        required: Required::When("with aerodynamics = stevens-lewis"),
        description: "∂C_n/∂(p b/2V), one per α.",
        example: "[0.052, -0.012, -0.013]",
        ..Key::BLANK
    },
];
