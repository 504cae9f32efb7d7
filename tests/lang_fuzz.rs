//! The front end never panics: random text, random token soup and randomly
//! mutated valid files all end in `Ok` or in errors that render.

use lambdamat::lang::parse_program;
use proptest::prelude::*;

const VALID: &[&str] = &[
    "# comment\nvar x\nmatrix A = [\n  (-5)+(9)*x, x^2 - 1/3*x;\n  3/4, (x+1)^2\n]\nsmith A\n",
    "var k1, k2, k3, k4\nprincipal k4\nmatrix A = [k1, k2; k3, k4]\nmatrix U = [1, 0; -k3, k1]\nmatrix D = [1, 0; 0, k1*k4 - k2*k3]\nmatrix V = [1, -k2; 0, 1]\ncheck smith A with U, D, V\n",
    include_str!("data/peers_3x3.lmx"),
    "param nu = 1/4\nparam gamma = (1 - 2*nu)/(2 - 2*nu)\nvar x\nmatrix E = []\nmatrix B = [gamma*x^2, 0.5;]\n",
    include_str!("../examples/hertz_stick.lmx"),
    "operator a = int(0..x) dt\noperator b = 2*id - x^2*id + int(x..1) (t - x) dt/3\nunknown p, q\n\
     equation b*a p - 2*a*q + p = x\nequation -a p + a^2 q - b q = sqrt(x)\n\
     output S = 1 + 1/3*int(0..1) q(t)*(1 - sqrt(1 - t^2)) dt - int(0..1/2) p(x) dx\n",
];

/// Tokens besides the keywords (which come from the language itself).
const OTHER_TOKENS: &[&str] = &[
    "x",
    "t",
    "k1",
    "A",
    "0",
    "1",
    "0.5",
    "(",
    ")",
    "[",
    "]",
    ",",
    ";",
    "+",
    "-",
    "*",
    "/",
    "^",
    "=",
    "..",
    "#",
    "\n",
    " ",
    "κ",
    "\u{0}",
    "é",
    "999999999999999999999",
];

fn check(src: &str) {
    if let Err(e) = parse_program(src, "fuzz.lmx") {
        assert!(!e.is_empty());
        let text = e.render();
        assert!(text.contains("fuzz.lmx:"), "{text}");
    }
}

#[derive(Clone, Debug)]
enum Edit {
    Insert(usize, String),
    Delete(usize, usize),
    Replace(usize, String),
}

fn apply(src: &str, edits: &[Edit]) -> String {
    let mut chars: Vec<char> = src.chars().collect();
    for e in edits {
        let n = chars.len().max(1);
        match e {
            Edit::Insert(at, s) => {
                let at = at % (chars.len() + 1);
                chars.splice(at..at, s.chars());
            }
            Edit::Delete(at, len) => {
                let at = at % n;
                let end = (at + len).min(chars.len());
                if at < end {
                    chars.drain(at..end);
                }
            }
            Edit::Replace(at, s) => {
                if !chars.is_empty() {
                    let at = at % chars.len();
                    chars.splice(at..at + 1, s.chars());
                }
            }
        }
    }
    chars.into_iter().collect()
}

fn token() -> impl Strategy<Value = String> {
    prop::sample::select(tokens()).prop_map(str::to_string)
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (any::<usize>(), token()).prop_map(|(a, s)| Edit::Insert(a, s)),
        (any::<usize>(), 1usize..6).prop_map(|(a, l)| Edit::Delete(a, l)),
        (any::<usize>(), token()).prop_map(|(a, s)| Edit::Replace(a, s)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn random_text_never_panics(s in "\\PC{0,200}") {
        check(&s);
    }

    #[test]
    fn token_soup_never_panics(toks in prop::collection::vec(token(), 0..60)) {
        check(&toks.join(" "));
        check(&toks.concat());
    }

    #[test]
    fn mutated_valid_files_never_panic(
        which in 0..VALID.len(),
        edits in prop::collection::vec(edit(), 1..6),
    ) {
        check(&apply(VALID[which], &edits));
    }
}

#[test]
fn valid_seeds_are_valid() {
    for src in VALID {
        assert!(parse_program(src, "v.lmx").is_ok(), "{src}");
    }
}

/// Every keyword of the language plus the other tokens.
fn tokens() -> Vec<&'static str> {
    lambdamat::lang::keywords::KEYWORDS
        .iter()
        .chain(OTHER_TOKENS)
        .copied()
        .collect()
}
