//! Every shipped model builds from the proved equations, with every strategy, and verifies.

use eom_codegen::model::Model;

#[test]
fn every_model_builds_and_verifies_with_every_strategy() {
    for model in Model::all() {
        for &strategy in model.strategies() {
            let system = model.system(strategy).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(system.outputs.len(), system.state.len(), "{}", system.name);
        }
    }
}
