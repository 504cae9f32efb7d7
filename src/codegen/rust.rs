//! Expressions as Rust source. [`Body`] prints an [`Expr`] so that the
//! Rust code performs the same floating-point operations in the same order
//! as the closure [`crate::plan::compile::compile`] builds: constant
//! subtrees folded to one literal (printed so it reads back bit for bit),
//! the same special cases for powers, every binary operation grouped as in
//! the tree. Long expressions are split into `let` bindings, which changes
//! nothing numerically and keeps every line short (so `rustfmt` leaves the
//! output alone). This file owns printing only; which expressions to print
//! is [`super`]'s business.
use crate::plan::compile::{AbelParts, const_exponent};
use crate::system::expr::Expr;

/// Precedence of a printed expression: what it may appear inside of
/// without parentheses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Sum,
    Product,
    Unary,
    Atom,
}

/// Longest expression kept inline (counting a few columns per operand);
/// longer subexpressions get a `let`.
const INLINE: usize = 80;

/// The body of a generated function: `let` bindings and a final expression.
#[derive(Debug, Default)]
pub struct Body {
    lets: Vec<String>,
}

/// A printed subexpression.
struct Code {
    text: String,
    prec: Prec,
}

impl Code {
    fn new(text: impl Into<String>, prec: Prec) -> Code {
        Code {
            text: text.into(),
            prec,
        }
    }
}

/// The constants of `std::f64::consts` by name, printed by name when a
/// value equals one exactly.
const NAMED: [(&str, f64); 19] = {
    use std::f64::consts::*;
    [
        ("PI", PI),
        ("TAU", TAU),
        ("FRAC_PI_2", FRAC_PI_2),
        ("FRAC_PI_3", FRAC_PI_3),
        ("FRAC_PI_4", FRAC_PI_4),
        ("FRAC_PI_6", FRAC_PI_6),
        ("FRAC_PI_8", FRAC_PI_8),
        ("FRAC_1_PI", FRAC_1_PI),
        ("FRAC_2_PI", FRAC_2_PI),
        ("FRAC_2_SQRT_PI", FRAC_2_SQRT_PI),
        ("SQRT_2", SQRT_2),
        ("FRAC_1_SQRT_2", FRAC_1_SQRT_2),
        ("E", E),
        ("LOG2_E", LOG2_E),
        ("LOG2_10", LOG2_10),
        ("LOG10_E", LOG10_E),
        ("LOG10_2", LOG10_2),
        ("LN_2", LN_2),
        ("LN_10", LN_10),
    ]
};

/// A float literal that reads back as exactly `v` (a constant of
/// `std::f64::consts` by its name).
pub fn literal(v: f64) -> String {
    if let Some((name, _)) = NAMED.iter().find(|(_, c)| c.to_bits() == v.abs().to_bits()) {
        let sign = if v < 0.0 { "-" } else { "" };
        return format!("{sign}std::f64::consts::{name}");
    }
    if v.is_nan() {
        "f64::NAN".into()
    } else if v == f64::INFINITY {
        "f64::INFINITY".into()
    } else if v == f64::NEG_INFINITY {
        "f64::NEG_INFINITY".into()
    } else {
        format!("{v:?}")
    }
}

fn lit(v: f64) -> Code {
    let text = literal(v);
    let prec = if text.starts_with('-') {
        Prec::Unary
    } else {
        Prec::Atom
    };
    Code::new(text, prec)
}

impl Body {
    /// A new, empty body.
    pub fn new() -> Body {
        Body::default()
    }

    /// The function body for `e` as `compile(e)` evaluates it, one line
    /// per entry (without indentation).
    pub fn expr(mut self, e: &Expr) -> Vec<String> {
        let c = self.node(e);
        self.finish(c)
    }

    /// The function body for the smooth factor of an Abel kernel, as
    /// `smooth_factor(parts)` evaluates it.
    pub fn abel(mut self, parts: &AbelParts) -> Vec<String> {
        // The closure computes ((scale·f₁)·f₂)…; multiplying by 1 is
        // exact, and so is negating, so ±1 scales are left out or become
        // a sign.
        let mut acc: Option<Code> = match parts.scale {
            1.0 => None,
            -1.0 if !parts.factors.is_empty() => None,
            s => Some(lit(s)),
        };
        let negate = parts.scale == -1.0 && !parts.factors.is_empty();
        for (k, (f, p)) in parts.factors.iter().enumerate() {
            let inner = self.node(f);
            let mut fc = self.pow_f(inner, *p);
            if k == 0 && negate {
                fc = Code::new(format!("-{}", self.wrap_neg(fc)), Prec::Unary);
            }
            acc = Some(match acc {
                None => fc,
                Some(a) => self.binary(a, "*", fc, Prec::Product),
            });
        }
        let c = acc.unwrap_or_else(|| lit(parts.scale));
        self.finish(c)
    }

    fn finish(mut self, c: Code) -> Vec<String> {
        let mut lines = std::mem::take(&mut self.lets);
        lines.push(c.text);
        lines
    }

    /// Binds `c` to a fresh name.
    fn bind(&mut self, c: Code) -> Code {
        let name = format!("v{}", self.lets.len() + 1);
        self.lets.push(format!("let {name} = {};", c.text));
        Code::new(name, Prec::Atom)
    }

    /// Binds the longest of `parts` to names until together they fit in
    /// [`INLINE`] columns (names and literals are never bound).
    fn fit(&mut self, parts: Vec<Code>) -> Vec<Code> {
        let mut parts: Vec<Option<Code>> = parts.into_iter().map(Some).collect();
        loop {
            let total: usize = parts.iter().flatten().map(|c| c.text.len() + 3).sum();
            if total <= INLINE {
                break;
            }
            let longest = parts
                .iter()
                .enumerate()
                .filter(|(_, c)| c.as_ref().is_some_and(|c| c.text.contains(['(', ' '])))
                .max_by_key(|(_, c)| c.as_ref().map_or(0, |c| c.text.len()))
                .map(|(i, _)| i);
            let Some(i) = longest else { break };
            let c = parts[i].take().expect("present");
            parts[i] = Some(self.bind(c));
        }
        parts.into_iter().flatten().collect()
    }

    fn paren(c: Code, need: Prec) -> String {
        if c.prec < need {
            format!("({})", c.text)
        } else {
            c.text
        }
    }

    /// The operand of a unary minus: never starting with another `-`.
    fn wrap_neg(&mut self, c: Code) -> String {
        let c = self.fit(vec![c]).pop().expect("one");
        if c.prec < Prec::Unary || c.text.starts_with('-') {
            format!("({})", c.text)
        } else {
            c.text
        }
    }

    fn binary(&mut self, a: Code, op: &str, b: Code, prec: Prec) -> Code {
        // Left-associative: the right operand binds tighter.
        let right = match prec {
            Prec::Sum => Prec::Product,
            _ => Prec::Unary,
        };
        let mut ab = self.fit(vec![a, b]);
        let b = ab.pop().expect("two");
        let a = ab.pop().expect("two");
        let a = Self::paren(a, prec);
        let b = if b.text.starts_with('-') {
            format!("({})", b.text)
        } else {
            Self::paren(b, right)
        };
        Code::new(format!("{a} {op} {b}"), prec)
    }

    fn call(&mut self, f: &str, args: Vec<Code>) -> Code {
        let args: Vec<String> = self.fit(args).into_iter().map(|a| a.text).collect();
        Code::new(format!("f64::{f}({})", args.join(", ")), Prec::Atom)
    }

    /// `compile(e)`, printed.
    fn node(&mut self, e: &Expr) -> Code {
        if !e.uses_x() && !e.uses_t() {
            return lit(e.eval(0.0, 0.0));
        }
        match e {
            Expr::X => Code::new("x", Prec::Atom),
            Expr::T => Code::new("t", Prec::Atom),
            Expr::Neg(a) => {
                let a = self.node(a);
                Code::new(format!("-{}", self.wrap_neg(a)), Prec::Unary)
            }
            Expr::Add(a, b) => self.bin(a, "+", b, Prec::Sum),
            Expr::Sub(a, b) => self.bin(a, "-", b, Prec::Sum),
            Expr::Mul(a, b) => self.bin(a, "*", b, Prec::Product),
            Expr::Div(a, b) => self.bin(a, "/", b, Prec::Product),
            Expr::Pow(a, b) => match const_exponent(b) {
                Some(p) => {
                    let a = self.node(a);
                    self.power(a, p)
                }
                None => {
                    let (a, b) = (self.node(a), self.node(b));
                    self.call("powf", vec![a, b])
                }
            },
            Expr::Call(f, a) if !f.is_f64_method() => {
                let a = self.node(a);
                let a = self.fit(vec![a]).pop().expect("one");
                Code::new(
                    format!("lambdamat::standalone::{}({})", f.name(), a.text),
                    Prec::Atom,
                )
            }
            Expr::Call(f, a) => {
                let a = self.node(a);
                self.call(f.name(), vec![a])
            }
            // Constants and π are folded above.
            Expr::Const(_) | Expr::Pi => lit(e.eval(0.0, 0.0)),
        }
    }

    fn bin(&mut self, a: &Expr, op: &str, b: &Expr, prec: Prec) -> Code {
        let (a, b) = (self.node(a), self.node(b));
        self.binary(a, op, b, prec)
    }

    /// `power(f, p)` of `compile.rs`, printed.
    fn power(&mut self, a: Code, p: f64) -> Code {
        if p == 1.0 {
            a
        } else if p == 0.5 {
            self.call("sqrt", vec![a])
        } else if p == -0.5 {
            let s = self.call("sqrt", vec![a]);
            self.binary(lit(1.0), "/", s, Prec::Product)
        } else if p.fract() == 0.0 && p.abs() < 64.0 {
            let a = self.fit(vec![a]).pop().expect("one");
            Code::new(format!("f64::powi({}, {})", a.text, p as i32), Prec::Atom)
        } else {
            self.call("powf", vec![a, lit(p)])
        }
    }

    /// `pow_f(v, p)` of `compile.rs`, printed.
    fn pow_f(&mut self, a: Code, p: f64) -> Code {
        if p == -1.0 {
            self.binary(lit(1.0), "/", a, Prec::Product)
        } else {
            self.power(a, p)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn expr(src: &str) -> Expr {
        let text = format!("operator k = int(0..1) {src} dt\nunknown p\nequation k p = 1\n");
        let p = crate::lang::parse_program(&text, "t.lmx").expect("parses");
        match &p.operators[0].terms[0] {
            crate::system::Term::Integral { kernel, .. } => kernel.clone(),
            other => panic!("{other:?}"),
        }
    }

    fn one_line(src: &str) -> String {
        let lines = Body::new().expr(&expr(src));
        assert_eq!(lines.len(), 1, "{lines:?}");
        lines[0].clone()
    }

    #[test]
    fn grouping_follows_the_tree() {
        assert_eq!(one_line("x - (t - x)"), "x - (t - x)");
        assert_eq!(one_line("(x - t) - x"), "x - t - x");
        assert_eq!(one_line("x/(t*x)"), "x / (t * x)");
        assert_eq!(one_line("-(x*t)"), "-(x * t)");
        assert_eq!(one_line("x*(-t)"), "x * (-t)");
        assert_eq!(one_line("x^2 + sqrt(t)"), "f64::powi(x, 2) + f64::sqrt(t)");
        assert_eq!(one_line("(x + t)^(-1/2)"), "1.0 / f64::sqrt(x + t)");
        assert_eq!(one_line("x^(1/3)"), "f64::powf(x, 0.3333333333333333)");
        assert_eq!(one_line("2^x"), "f64::powf(2.0, x)");
        assert_eq!(one_line("x*(1/3 - 1)"), "x * (-0.6666666666666666)");
        assert_eq!(one_line("pi/2*x"), "std::f64::consts::FRAC_PI_2 * x");
        assert_eq!(one_line("-pi*x"), "-std::f64::consts::PI * x");
    }

    #[test]
    fn literals_read_back_exactly() {
        for v in [1.0 / 3.0, -2.5e-300, 1e22, 1.2345, 0.1, -0.0] {
            assert_eq!(literal(v).parse::<f64>().unwrap().to_bits(), v.to_bits());
        }
        assert_eq!(literal(f64::NAN), "f64::NAN");
        assert_eq!(literal(-std::f64::consts::PI), "-std::f64::consts::PI");
        assert_eq!(literal(std::f64::consts::LN_2), "std::f64::consts::LN_2");
    }

    #[test]
    fn long_expressions_are_split_into_lets() {
        let src = "exp(x*t)*ln(1 + t^2)/(2 + x) + sqrt(abs(x - t))*(x^3 - t^3)/(1 + x*t)^2 - x";
        let lines = Body::new().expr(&expr(src));
        assert!(lines.len() > 1, "{lines:?}");
        assert!(lines.iter().all(|l| l.len() <= 92), "{lines:?}");
        assert!(
            lines[..lines.len() - 1]
                .iter()
                .all(|l| l.starts_with("let v"))
        );
    }
}
