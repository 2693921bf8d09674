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

/// The model contract each generated file implements adds nothing the fold-back proof has not
/// seen: every method's body is one call of the file's proved function of the same name on
/// the same arguments (the Jacobians through `eom_kernel::scatter` onto their proved pattern,
/// the potential energy wrapped in `Some`), and every constant names the file's own.
#[test]
fn the_emitted_model_contract_only_delegates_to_proved_functions() {
    use quote::ToTokens;
    for model in Model::all() {
        let generated = eom_codegen::emit::generate(model).unwrap();
        let file = syn::parse_file(&generated.source).unwrap();
        let contract = file
            .items
            .iter()
            .find_map(|item| match item {
                syn::Item::Impl(block) if block.trait_.is_some() => Some(block),
                _ => None,
            })
            .unwrap_or_else(|| panic!("{}: no contract", generated.name));
        let header = contract.to_token_stream().to_string();
        assert!(
            header.contains("eom_kernel :: Model <"),
            "{}",
            generated.name
        );
        assert!(
            header.contains("for Coefficients < T >"),
            "{}",
            generated.name
        );
        for item in &contract.items {
            let text = item.to_token_stream().to_string();
            let body = match item {
                syn::ImplItem::Fn(function) => function.block.to_token_stream().to_string(),
                syn::ImplItem::Const(constant) => constant.expr.to_token_stream().to_string(),
                _ => panic!("{}: unexpected {text}", generated.name),
            };
            let allowed = [
                format!("\"{}\"", generated.name),
                "STATE".into(),
                "INPUTS".into(),
                "& STATE_JACOBIAN".into(),
                "& INPUT_JACOBIAN".into(),
                "{ rhs (self , state , input) }".into(),
                "{ kinetic_energy (self , state) }".into(),
                "{ Some (potential_energy (self , state)) }".into(),
                "{ eom_kernel :: scatter (& STATE_JACOBIAN , state_jacobian (self , state , input)) }"
                    .into(),
                "{ eom_kernel :: scatter (& INPUT_JACOBIAN , input_jacobian (self , state , input)) }"
                    .into(),
            ];
            assert!(allowed.contains(&body), "{}: {body}", generated.name);
        }
        let potential = contract
            .items
            .iter()
            .any(|item| matches!(item, syn::ImplItem::Fn(f) if f.sig.ident == "potential_energy"));
        assert_eq!(potential, generated.potential_energy, "{}", generated.name);
    }
}
