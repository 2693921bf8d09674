//! Prints the generated source of one model: `cargo run -p eom-codegen --example print_model -- spatial_xz_euler`.

use eom_codegen::emit::generate;
use eom_codegen::model::Model;

fn main() {
    let wanted = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "spatial_principal_euler".into());
    match Model::all().into_iter().find(|m| m.name() == wanted) {
        Some(model) => match generate(model) {
            Ok(generated) => print!("{}", generated.source),
            Err(error) => eprintln!("error: {error}"),
        },
        None => eprintln!("error: no model named {wanted}"),
    }
}
