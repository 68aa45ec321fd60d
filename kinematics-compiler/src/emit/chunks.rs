//! A body's statements in chunks at its block marks, for a debug build's stack.
//!
//! Unoptimised, every `let` and temporary of a function keeps its own stack slot for the whole
//! call: a robot's body of thousands of lane operations (a slot of 32 to 64 bytes each) needed
//! megabytes, more than a test thread's stack. So each stretch of statements that ends in a block
//! mark (`T::block_mark(k);`, about every [`BLOCK_MARK_OPS`](kinematics_core::BLOCK_MARK_OPS)
//! operations) becomes a closure run by the core's `chunk`, whose value is a tuple of the names
//! the stretch binds and the code after it reads, and the code after it reads them there:
//! `let chunk_0 = chunk(|| { let t4 = ..; let t5 = ..; T::block_mark(1); (t4, t5) });` and then
//! `chunk_0.1` for `t5`. In a debug build the closure is a call of its own, so only one
//! stretch's slots are live at a time, and each name it returns is held once, in its tuple (not
//! copied out of it again). An optimised build does not see the chunks: the body is emitted twice,
//! as written (`#[cfg(not(debug_assertions))]`, always inlined) and in chunks
//! (`#[cfg(debug_assertions)]`), the statements the same tokens in the same order. (One body with
//! the chunks' closures always inlined measured the spherized Panda's `collides_batch_f32` 1.37
//! times as long as before, criterion, `cargo bench --bench collision`.)

use std::collections::BTreeMap;

use proc_macro2::{Delimiter, Group, Ident, Literal, TokenStream, TokenTree};
use quote::{format_ident, quote};

/// A generic body as items: `attrs` and `signature` (`pub fn name<T: ..>(..) -> ..`) with `body`.
///
/// A body with block marks is two items: the body as written, `#[inline(always)]`, without
/// `debug_assertions` (an optimised build's code is the statements as they are, nothing around
/// them), and the body in chunks with them. A body without marks is one item, always inlined only
/// without `debug_assertions`.
pub(super) fn function(
    attrs: TokenStream,
    signature: TokenStream,
    body: TokenStream,
    private: &TokenStream,
) -> TokenStream {
    match chunked(body.clone(), private) {
        Some(chunked) => quote! {
            #attrs
            #[cfg(not(debug_assertions))]
            #[allow(clippy::inline_always)]
            #[inline(always)]
            #signature { #body }
            #attrs
            #[cfg(debug_assertions)]
            #signature { #chunked }
        },
        None => quote! {
            #attrs
            #[allow(clippy::inline_always)]
            #[cfg_attr(not(debug_assertions), inline(always))]
            #signature { #body }
        },
    }
}

/// `body` (statements, then the value) with every stretch of statements that ends in a block mark
/// run by `private::chunk`; `None` for a body without marks.
pub(super) fn chunked(body: TokenStream, private: &TokenStream) -> Option<TokenStream> {
    let (statements, value) = statements(body);
    if !statements.iter().any(|s| is_mark(s)) {
        return None;
    }
    // The last statement reading each name (the value counting as one past the last statement):
    // a stretch ending at statement `k` returns the names it binds that are read after `k`.
    let mut last_read: BTreeMap<String, usize> = BTreeMap::new();
    for (k, statement) in statements.iter().enumerate() {
        for name in idents(statement) {
            last_read.insert(name, k);
        }
    }
    for name in idents(&value) {
        last_read.insert(name, statements.len());
    }
    let mut out = TokenStream::new();
    // Each name a chunk returned, and where it is now: `chunk_3.4`.
    let mut held: BTreeMap<String, TokenStream> = BTreeMap::new();
    let mut stretch: Vec<Vec<TokenTree>> = Vec::new();
    let mut chunks = 0;
    for (k, statement) in statements.into_iter().enumerate() {
        let statement = reading_held(statement, &held);
        for name in bound_names(&statement) {
            held.remove(&name.to_string());
        }
        let mark = is_mark(&statement);
        stretch.push(statement);
        if mark {
            let tuple = format_ident!("chunk_{chunks}");
            chunks += 1;
            let names =
                chunk(&stretch, &tuple, |name| last_read.get(name).is_some_and(|&last| last > k), private, &mut out);
            for (i, name) in names.iter().enumerate() {
                let i = Literal::usize_unsuffixed(i);
                held.insert(name.to_string(), quote!(#tuple.#i));
            }
            stretch.clear();
        }
    }
    out.extend(stretch.into_iter().flatten());
    out.extend(rewritten(value, &held));
    Some(out)
}

/// One stretch as a closure run by `chunk` into `out`, its value the tuple `tuple` of what the
/// stretch binds and the code after it reads (`read_after`): those names, in order.
fn chunk(
    stretch: &[Vec<TokenTree>],
    tuple: &Ident,
    read_after: impl Fn(&str) -> bool,
    private: &TokenStream,
    out: &mut TokenStream,
) -> Vec<TokenTree> {
    let names: Vec<TokenTree> =
        stretch.iter().flat_map(|s| bound_names(s)).filter(|name| read_after(&name.to_string())).collect();
    let statements: TokenStream = stretch.iter().flatten().cloned().collect();
    let inline = quote!(#[cfg_attr(not(debug_assertions), inline(always))]);
    out.extend(if names.is_empty() {
        quote!(#private::chunk(#inline || { #statements });)
    } else {
        quote!(let #tuple = #private::chunk(#inline || { #statements (#(#names,)*) });)
    });
    names
}

/// `statement` with every name a chunk returned read from its tuple (`t5` as `chunk_3.4`): in
/// a `let`, after its `=`, so its pattern stays as written.
fn reading_held(statement: Vec<TokenTree>, held: &BTreeMap<String, TokenStream>) -> Vec<TokenTree> {
    if held.is_empty() {
        return statement;
    }
    let is_let = matches!(statement.first(), Some(TokenTree::Ident(first)) if first == "let");
    let pattern_end = if is_let {
        statement.iter().position(|t| matches!(t, TokenTree::Punct(p) if p.as_char() == '=')).map_or(0, |k| k + 1)
    } else {
        0
    };
    let mut statement = statement;
    let reads = statement.split_off(pattern_end);
    statement.extend(rewritten(reads, held));
    statement
}

/// `tokens` with every name in `held` replaced by its place, groups included.
fn rewritten(tokens: Vec<TokenTree>, held: &BTreeMap<String, TokenStream>) -> Vec<TokenTree> {
    let mut out = Vec::with_capacity(tokens.len());
    for token in tokens {
        match token {
            TokenTree::Ident(name) => match held.get(&name.to_string()) {
                Some(place) => out.extend(place.clone()),
                None => out.push(TokenTree::Ident(name)),
            },
            TokenTree::Group(group) => {
                let inner = rewritten(group.stream().into_iter().collect(), held);
                let mut new = Group::new(group.delimiter(), inner.into_iter().collect());
                new.set_span(group.span());
                out.push(TokenTree::Group(new));
            }
            other => out.push(other),
        }
    }
    out
}

/// The statements of `body` (each with its `;`), and what follows the last one (the value).
fn statements(body: TokenStream) -> (Vec<Vec<TokenTree>>, Vec<TokenTree>) {
    let mut statements = Vec::new();
    let mut current = Vec::new();
    for token in body {
        let end = matches!(&token, TokenTree::Punct(p) if p.as_char() == ';');
        current.push(token);
        if end {
            statements.push(std::mem::take(&mut current));
        }
    }
    (statements, current)
}

/// Whether `statement` is a block mark, `T::block_mark(k);`.
fn is_mark(statement: &[TokenTree]) -> bool {
    matches!(statement, [TokenTree::Ident(t), TokenTree::Punct(_), TokenTree::Punct(_), TokenTree::Ident(mark), ..]
        if t == "T" && mark == "block_mark")
}

/// The names a `let` statement binds: the identifiers of its pattern (the emitter writes names,
/// `_`, arrays and tuples of them, no types), none for another statement.
fn bound_names(statement: &[TokenTree]) -> Vec<TokenTree> {
    let [TokenTree::Ident(first), rest @ ..] = statement else { return Vec::new() };
    if first != "let" {
        return Vec::new();
    }
    let pattern =
        rest.iter().take_while(|t| !matches!(t, TokenTree::Punct(p) if p.as_char() == '=' || p.as_char() == ':'));
    let mut names = Vec::new();
    collect_names(pattern, &mut names);
    names
}

/// Every identifier in `tokens`, groups included, in order (repeated as often as it appears).
fn idents(tokens: &[TokenTree]) -> Vec<String> {
    let mut out = Vec::new();
    for token in tokens {
        match token {
            TokenTree::Ident(name) => out.push(name.to_string()),
            TokenTree::Group(group) => {
                let inner: Vec<TokenTree> = group.stream().into_iter().collect();
                out.extend(idents(&inner));
            }
            _ => {}
        }
    }
    out
}

fn collect_names<'a>(tokens: impl Iterator<Item = &'a TokenTree>, names: &mut Vec<TokenTree>) {
    for token in tokens {
        match token {
            TokenTree::Ident(name) if name != "_" && name != "mut" && name != "ref" => names.push(token.clone()),
            TokenTree::Group(group) if group.delimiter() != Delimiter::Brace => {
                let inner: Vec<TokenTree> = group.stream().into_iter().collect();
                collect_names(inner.iter(), names);
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::chunked;
    use quote::quote;

    #[test]
    fn a_body_without_marks_is_unchanged() {
        let body = quote!(let [q1, q2] = *q; let t0 = q1 + q2; [t0, q1]);
        assert!(chunked(body, &quote!(p)).is_none());
    }

    #[test]
    fn each_stretch_ending_in_a_mark_is_a_chunk_binding_what_is_read_after_it() {
        let body = quote!(
            let [q1, _, q3] = *q;
            let ([s1, _], [c1, c2]) = T::sin_cos_many([q1, q3]);
            T::block_mark(1);
            let t0 = s1 * c2;
            T::block_mark(2);
            let t1 = t0 + c1;
            [t1, q3]
        );
        let expected = quote!(
            let chunk_0 = p::chunk(#[cfg_attr(not(debug_assertions), inline(always))] || {
                let [q1, _, q3] = *q;
                let ([s1, _], [c1, c2]) = T::sin_cos_many([q1, q3]);
                T::block_mark(1);
                (q3, s1, c1, c2,)
            });
            let chunk_1 = p::chunk(#[cfg_attr(not(debug_assertions), inline(always))] || {
                let t0 = chunk_0.1 * chunk_0.3;
                T::block_mark(2);
                (t0,)
            });
            let t1 = chunk_1.0 + chunk_0.2;
            [t1, chunk_0.0]
        );
        assert_eq!(chunked(body, &quote!(p)).map(|c| c.to_string()), Some(expected.to_string()));
    }

    #[test]
    fn a_stretch_that_binds_nothing_is_run_as_a_statement() {
        let body = quote!(let _ = q; T::block_mark(1); 0);
        let expected =
            quote!(p::chunk(#[cfg_attr(not(debug_assertions), inline(always))] || { let _ = q; T::block_mark(1); }); 0);
        assert_eq!(chunked(body, &quote!(p)).map(|c| c.to_string()), Some(expected.to_string()));
    }
}
