//! One generated function's body: which values get a `let`, their names, and the inline
//! expressions of the rest.
//!
//! A value gets a `let` of its own when it has a name in the system (a stage, an output), when
//! the function reads it more than once, or when it is a reciprocal; anything else is written
//! inline where it is used, parenthesised where a sum would bind wrongly and on the right of a
//! product, so the code multiplies in the order the program does. Products list their factors
//! as the chapter writes them: coefficients, symbols, named values, sines, cosines.

use super::program::{Function, Id, Node, Program, identifier, unique};
use super::rust::{ident, rational_tokens};
use proc_macro2::TokenStream;
use quote::quote;

/// Writes one function's nodes as Rust: names, `let`s and inline expressions.
pub(super) struct Writer<'a> {
    program: &'a Program,
    uses: Vec<u32>,
    reached: Vec<bool>,
    names: Vec<Option<String>>,
    defined: Vec<bool>,
    taken: Vec<String>,
}

impl<'a> Writer<'a> {
    pub(super) fn new(program: &'a Program, function: &Function) -> Self {
        let mut writer = Writer {
            program,
            uses: program.uses(function),
            reached: program.reached(function),
            names: vec![None; program.nodes.len()],
            defined: vec![false; program.nodes.len()],
            taken: Vec::new(),
        };
        for named in function.stages.iter().chain(&function.outputs) {
            let index = named.id.index();
            if writer.names[index].is_none() && !writer.is_leaf(named.id) {
                writer.names[index] = Some(writer.take(&named.name));
            }
        }
        writer
    }

    fn take(&mut self, name: &str) -> String {
        let name = unique(name, self.taken.iter().map(String::as_str));
        self.taken.push(name.clone());
        name
    }

    /// Variables, sines and cosines: bound before the body, never defined in it.
    fn is_leaf(&self, id: Id) -> bool {
        matches!(
            self.program.node(id),
            Node::Variable(_) | Node::Sin(_) | Node::Cos(_)
        )
    }

    /// The `let [..] = *state;` pattern: a name for each entry the function reads, `_` else.
    pub(super) fn destructure(&mut self, symbols: &[&str]) -> Vec<TokenStream> {
        symbols
            .iter()
            .map(|symbol| {
                let id = self.program.nodes.iter().enumerate().find_map(|(i, node)| {
                    matches!(node, Node::Variable(s) if s == symbol).then_some(i)
                });
                match id {
                    Some(index) if self.reached[index] => {
                        let name = self.take(&identifier(symbol));
                        self.names[index] = Some(name.clone());
                        self.defined[index] = true;
                        let name = ident(&name);
                        quote! { #name }
                    }
                    _ => quote! { _ },
                }
            })
            .collect()
    }

    /// One `eom_kernel::sin_cos` call for every angle the function reads.
    pub(super) fn sin_cos(&mut self) -> TokenStream {
        let angles = self.program.angles(&self.function_stub());
        if angles.is_empty() {
            return TokenStream::new();
        }
        let mut pairs = Vec::new();
        let mut arguments = Vec::new();
        for angle in angles {
            let angle_name = self.names[angle.index()]
                .clone()
                .expect("an angle is a state entry");
            let mut pair = Vec::new();
            for (prefix, is_sin) in [("sin", true), ("cos", false)] {
                let found = self.program.nodes.iter().enumerate().find_map(|(i, node)| {
                    let matches = match node {
                        Node::Sin(a) => is_sin && *a == angle,
                        Node::Cos(a) => !is_sin && *a == angle,
                        _ => false,
                    };
                    matches.then_some(i)
                });
                match found {
                    Some(index) if self.reached[index] => {
                        let name = self.take(&format!("{prefix}_{angle_name}"));
                        self.names[index] = Some(name.clone());
                        self.defined[index] = true;
                        let name = ident(&name);
                        pair.push(quote! { #name });
                    }
                    _ => pair.push(quote! { _ }),
                }
            }
            let (s, c) = (&pair[0], &pair[1]);
            pairs.push(quote! { (#s, #c) });
            let angle = ident(&angle_name);
            arguments.push(quote! { #angle });
        }
        quote! { let [#(#pairs),*] = eom_kernel::sin_cos([#(#arguments),*]); }
    }

    /// A function with every reached node as an output, for [`Program::angles`].
    fn function_stub(&self) -> Function {
        Function {
            stages: vec![],
            outputs: self
                .reached
                .iter()
                .enumerate()
                .filter(|(_, r)| **r)
                .map(|(i, _)| super::program::Named {
                    name: String::new(),
                    id: Id(i as u32),
                })
                .collect(),
        }
    }

    fn needs_let(&self, id: Id) -> bool {
        match self.program.node(id) {
            Node::Variable(_) | Node::Sin(_) | Node::Cos(_) => false,
            Node::Coefficient(_) | Node::Constant(_) => false,
            Node::Recip(_) => true,
            _ => self.names[id.index()].is_some() || self.uses[id.index()] >= 2,
        }
    }

    /// The `let`s that `id` needs, operands first, then its own if it has one.
    pub(super) fn define(&mut self, id: Id) -> Vec<TokenStream> {
        let mut lets = Vec::new();
        self.define_into(id, &mut lets);
        lets
    }

    fn define_into(&mut self, id: Id, lets: &mut Vec<TokenStream>) {
        if self.defined[id.index()] {
            return;
        }
        for child in self.program.node(id).children() {
            self.define_into(child, lets);
        }
        if self.needs_let(id) {
            let name = match self.names[id.index()].clone() {
                Some(name) => name,
                None => {
                    let name = self.take(&self.suggested_name(id));
                    self.names[id.index()] = Some(name.clone());
                    name
                }
            };
            let value = self.expression(id);
            let name = ident(&name);
            lets.push(quote! { let #name = #value; });
            self.defined[id.index()] = true;
        }
    }

    /// A name for a shared value: products of named leaves after their factors (`q_r`,
    /// `sin_theta_heading`), reciprocals after what they invert (`sec_theta`, `inv_norm2`).
    fn suggested_name(&self, id: Id) -> String {
        match self.program.node(id) {
            Node::Recip(of) => match self.program.node(*of) {
                Node::Cos(angle) => format!("sec_{}", self.plain_name(*angle)),
                _ => format!("inv_{}", self.plain_name(*of)),
            },
            _ => self
                .product_name(id)
                .unwrap_or_else(|| format!("shared_{}", id.0)),
        }
    }

    fn plain_name(&self, id: Id) -> String {
        self.names[id.index()]
            .clone()
            .or_else(|| self.product_name(id))
            .unwrap_or_else(|| format!("value_{}", id.0))
    }

    /// `a_b` for a product of named values or of such products.
    fn product_name(&self, id: Id) -> Option<String> {
        match self.program.node(id) {
            Node::Mul(a, b) => {
                let part = |x: Id| {
                    self.names[x.index()]
                        .clone()
                        .or_else(|| self.product_name(x))
                };
                let (a, b) = self.in_reading_order(*a, *b);
                Some(format!("{}_{}", part(a)?, part(b)?))
            }
            _ => None,
        }
    }

    /// The name of a defined value, or its expression written inline.
    pub(super) fn reference(&self, id: Id) -> TokenStream {
        match (&self.names[id.index()], self.defined[id.index()]) {
            (Some(name), true) => {
                let name = ident(name);
                quote! { #name }
            }
            _ => self.expression(id),
        }
    }

    /// An operand, parenthesised where a sum would otherwise bind wrongly; a product on the
    /// right of a product too, so the code multiplies in the order the program does.
    fn operand(&self, id: Id) -> TokenStream {
        self.operand_in(id, false)
    }

    fn operand_in(&self, id: Id, right_of_product: bool) -> TokenStream {
        let inline = !(self.names[id.index()].is_some() && self.defined[id.index()]);
        let compound = match self.program.node(id) {
            Node::Add(..) | Node::Sub(..) | Node::Neg(_) => true,
            Node::Mul(..) => right_of_product,
            _ => false,
        };
        let tokens = self.reference(id);
        if inline && compound {
            quote! { (#tokens) }
        } else {
            tokens
        }
    }

    /// The order in which a product lists its factors, as the chapter writes them:
    /// coefficients, then state and input symbols, named values, sines, cosines, reciprocals.
    fn reading_order(&self, id: Id) -> (u8, String) {
        let class = match self.program.node(id) {
            Node::Coefficient(_) | Node::Constant(_) => 0,
            Node::Variable(_) => 1,
            Node::Sin(_) => 3,
            Node::Cos(_) => 4,
            Node::Recip(_) => 5,
            _ if self.names[id.index()].is_some() => 2,
            _ => 6,
        };
        (class, self.names[id.index()].clone().unwrap_or_default())
    }

    fn in_reading_order(&self, a: Id, b: Id) -> (Id, Id) {
        if self.reading_order(b) < self.reading_order(a) {
            (b, a)
        } else {
            (a, b)
        }
    }

    /// The factors of a product written inline (not a named value), for a sum to fuse it:
    /// `a·b ± c` is written `mul_add(a, b, ±c)`, one fused multiply–add where the target has
    /// FMA and the product and the sum each rounded where it has not (`eom_kernel::mul_add`),
    /// so the default build's bits are those of `a * b ± c`.
    fn inline_product(&self, id: Id) -> Option<(Id, Id)> {
        let inline = !(self.names[id.index()].is_some() && self.defined[id.index()]);
        match self.program.node(id) {
            Node::Mul(a, b) if inline => Some(self.in_reading_order(*a, *b)),
            _ => None,
        }
    }

    pub(super) fn expression(&self, id: Id) -> TokenStream {
        match self.program.node(id) {
            Node::Variable(_) | Node::Sin(_) | Node::Cos(_) => self.reference(id),
            Node::Coefficient(index) => {
                let name = ident(&self.program.coefficients[*index].name);
                quote! { k.#name }
            }
            Node::Constant(c) => {
                let value = rational_tokens(c);
                quote! { T::from_subset(&#value) }
            }
            Node::Recip(of) => {
                let of = self.operand(*of);
                quote! { #of.simd_recip() }
            }
            Node::Neg(a) => {
                let a = self.operand(*a);
                quote! { -#a }
            }
            Node::Add(a, b) => {
                if let Some((x, y)) = self.inline_product(*b) {
                    let (x, y, a) = (self.reference(x), self.reference(y), self.reference(*a));
                    return quote! { mul_add(#x, #y, #a) };
                }
                if let Some((x, y)) = self.inline_product(*a) {
                    let (x, y, b) = (self.reference(x), self.reference(y), self.reference(*b));
                    return quote! { mul_add(#x, #y, #b) };
                }
                let (a, b) = (self.reference(*a), self.operand(*b));
                quote! { #a + #b }
            }
            Node::Sub(a, b) => {
                if let Some((x, y)) = self.inline_product(*b) {
                    let (x, y, a) = (self.operand(x), self.reference(y), self.reference(*a));
                    return quote! { mul_add(-#x, #y, #a) };
                }
                if let Some((x, y)) = self.inline_product(*a) {
                    let (x, y, b) = (self.reference(x), self.reference(y), self.operand(*b));
                    return quote! { mul_add(#x, #y, -#b) };
                }
                let (a, b) = (self.reference(*a), self.operand(*b));
                quote! { #a - #b }
            }
            Node::Mul(a, b) => {
                let (a, b) = self.in_reading_order(*a, *b);
                let (a, b) = (self.operand(a), self.operand_in(b, true));
                quote! { #a * #b }
            }
        }
    }
}
