//! NASA's NESC check cases as `data/nesc/cases.json` holds them: a case, and a tool's printed
//! values of a column at the checkpoints t = 0, 5, …, 30 s.

use crate::cli::root;
use serde_json::Value;

/// The international foot, m: the NESC tools' numbers are in it.
pub const FOOT: f64 = 0.3048;

/// Every case, as the file gives them.
pub fn cases() -> Vec<Value> {
    let text = std::fs::read_to_string(root().join("data/nesc/cases.json")).unwrap();
    let all: Value = serde_json::from_str(&text).unwrap();
    all["cases"].as_array().unwrap().clone()
}

/// Case `number`.
pub fn case(number: u64) -> Value {
    (cases().into_iter())
        .find(|c| c["number"] == number)
        .unwrap()
}

/// A tool's checkpoints of `column` in `case`, as numbers; `None` where it gives none.
pub fn column(case: &Value, name: &str, tool: &str) -> Option<Vec<f64>> {
    let values = case["checkpoints"][name][tool].as_array()?;
    Some(
        values
            .iter()
            .map(|v| v.as_str().unwrap().parse().unwrap())
            .collect(),
    )
}
