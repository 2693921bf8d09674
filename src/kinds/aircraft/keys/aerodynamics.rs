//! An aircraft scene's `[aerodynamics]` keys: the tables of the Stevens & Lewis form, or a
//! textbook's stability derivatives.

use super::AIRCRAFT;
use crate::scene::reference::{Key, Kind, Required, Shown};

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
    Key {
        path: "aerodynamics.derivatives.CL_0",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Lift coefficient at α = 0 with the elevator at 0 (the wind axes' C_L; C_X = C_L sin α − C_D cos α, C_Z = −C_L cos α − C_D sin α). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.41",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CL_alpha",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Lift per radian of α. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "4.44",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CL_q",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Lift per unit q c̄/(2V). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CL_elevator",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Lift per radian of elevator. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CD_0",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Drag coefficient at α = 0. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.05",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CD_alpha",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Drag per radian of α. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cm_0",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Pitching moment at α = 0 with the elevator at 0, about G. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cm_alpha",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Pitching moment per radian of α. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "-0.683",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cm_alpha_dot",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Pitching moment per unit α̇ c̄/(2V) (the downwash's lag at the tail): added once α̇ is known (α̇ depends on the lift, not on C_m). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cm_q",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Pitching moment per unit q c̄/(2V). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "-9.96",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cm_elevator",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Pitching moment per radian of elevator. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CL_alpha_dot",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Lift per unit α̇ c̄/(2V) (Etkin's C_zα̇ is −C_Lα̇ in the condition's stability axes): α̇ depends on the lift, so the model solves α̇ = α̇₀ + g α̇ for it, exactly (α̇ is affine in the lift). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CL_u",
        families: AIRCRAFT,
        unit: "per unit û",
        default: "0",
        required: Required::No,
        description: "Lift per û = (V − u₀)/u₀, u₀ the table's reference_speed (Etkin's C_zu is −C_Lu; per Mach, C_LM = C_Lu/M₀ at the table's Mach). The lift of the aerodynamics alone: the thrust is the engine's. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CD_u",
        families: AIRCRAFT,
        unit: "per unit û",
        default: "0",
        required: Required::No,
        description: "Drag per û = (V − u₀)/u₀ (Nelson's and Roskam's C_Du; Etkin's C_xu = −C_Du − 2 C_D0 for a thrust constant with speed, which the engine's constant thrust gives). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cm_u",
        families: AIRCRAFT,
        unit: "per unit û",
        default: "0",
        required: Required::No,
        description: "Pitching moment per û = (V − u₀)/u₀, about G. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CD_q",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Drag per unit q c̄/(2V) (Etkin's C_xq is −C_Dq in the condition's stability axes). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CD_elevator",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Drag per radian of elevator (Etkin's C_xδe is −C_Dδe in the condition's stability axes). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.reference_speed",
        families: AIRCRAFT,
        unit: "ft/s or m/s",
        default: "0",
        required: Required::No,
        description: "u₀, the airspeed the speed derivatives CL_u, CD_u, Cm_u are taken about (the table's flight condition; a trim elsewhere sees û ≠ 0). Required with them, refused without them.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CY_beta",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Side force per radian of β. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CY_p",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Side force per unit p b/(2V). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CY_r",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Side force per unit r b/(2V). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CY_aileron",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Side force per radian of aileron. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.CY_rudder",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Side force per radian of rudder. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cl_beta",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Rolling moment per radian of β. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cl_p",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Rolling moment per unit p b/(2V). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cl_r",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Rolling moment per unit r b/(2V). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cl_aileron",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Rolling moment per radian of aileron. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cl_rudder",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Rolling moment per radian of rudder. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cn_beta",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Yawing moment per radian of β. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cn_p",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Yawing moment per unit p b/(2V). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cn_r",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Yawing moment per unit r b/(2V). Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cn_aileron",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Yawing moment per radian of aileron. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "aerodynamics.derivatives.Cn_rudder",
        families: AIRCRAFT,
        unit: "per rad",
        default: "0",
        required: Required::No,
        description: "Yawing moment per radian of rudder. Read with aerodynamics = derivatives; a term not given is 0.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
];
