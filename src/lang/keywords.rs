//! The reserved words of the language, shared by the parser's error messages,
//! the validator and the pretty-printer. The grammar's `keyword` rule must
//! list exactly these; a unit test checks that it does.

/// Every reserved word; none of them can name a symbol, matrix, parameter,
/// unknown, operator or output.
pub const KEYWORDS: &[&str] = &[
    "var",
    "principal",
    "matrix",
    "smith",
    "check",
    "with",
    "param",
    "unknown",
    "operator",
    "equation",
    "solve",
    "for",
    "output",
    "int",
    "pv",
    "id",
    "pi",
    "sqrt",
    "ln",
    "abs",
    "exp",
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "acot",
    "sinh",
    "cosh",
    "tanh",
    "dt",
    "dx",
    "relation",
    "scalar",
    "singular",
    "condition",
    "inequality",
    "on",
    "in",
    "at",
];

/// Whether `word` is reserved.
pub fn is_keyword(word: &str) -> bool {
    KEYWORDS.contains(&word)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grammar_reserves_exactly_these_words() {
        let grammar = include_str!("../../grammar/lambdamat.pest");
        let start = grammar.find("keyword = @{").expect("keyword rule");
        let end = start + grammar[start..].find('}').expect("end of rule");
        let rule = &grammar[start..end];
        let mut listed: Vec<&str> = rule.split('"').skip(1).step_by(2).collect();
        listed.sort_unstable();
        let mut ours = KEYWORDS.to_vec();
        ours.sort_unstable();
        assert_eq!(listed, ours);
    }

    #[test]
    fn every_keyword_is_refused_as_a_name_and_longer_words_are_not() {
        // `sinh`, `cosh`, `tanh` and `singular` were once taken for names:
        // `sin` matched first and the word went on.
        for kw in KEYWORDS {
            let src = format!("param {kw} = 1\n");
            let e = crate::lang::parser::parse_file(&src).expect_err(kw);
            assert!(
                e.message.contains("reserved keyword"),
                "{kw}: {}",
                e.message
            );
            for longer in [format!("{kw}2"), format!("{kw}_"), format!("{kw}x")] {
                let src = format!("param {longer} = 1\n");
                assert!(crate::lang::parser::parse_file(&src).is_ok(), "{longer}");
            }
        }
    }
}
