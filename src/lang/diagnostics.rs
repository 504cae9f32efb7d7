//! Rendering front-end errors for people: the only place in the crate that
//! turns byte spans into line:column. [`LangErrors`] owns the source text and
//! every [`LangError`] found in it; it renders them as miette diagnostics
//! (source line, caret, label, help) for the terminal and as plain text via
//! [`LangErrors::render`] for golden tests. It must not decide *what* is
//! wrong: parser and validator do that.

use std::fmt;

use miette::{Diagnostic, LabeledSpan, NamedSource, SourceCode};

use super::ast::Span;
use super::error::LangError;

/// Every error found in one source file, with the file to show them in.
#[derive(Debug)]
pub struct LangErrors {
    source: NamedSource<String>,
    errors: Vec<LangError>,
}

impl LangErrors {
    /// Bundles `errors` found in `text` (the file called `filename`).
    pub fn new(filename: &str, text: &str, errors: Vec<LangError>) -> LangErrors {
        LangErrors {
            source: NamedSource::new(filename, text.to_string()),
            errors,
        }
    }

    /// The name of the file the errors are in.
    pub fn filename(&self) -> &str {
        self.source.name()
    }

    /// The number of errors.
    pub fn len(&self) -> usize {
        self.errors.len()
    }

    /// Whether there are none (never the case for a returned `Err`).
    pub fn is_empty(&self) -> bool {
        self.errors.is_empty()
    }

    /// The errors, in source order.
    pub fn errors(&self) -> &[LangError] {
        &self.errors
    }

    /// The 1-based line and column (in characters) where `span` starts.
    pub fn line_col(&self, span: Span) -> (usize, usize) {
        line_col(self.source.inner(), span.start)
    }

    /// Plain-text rendering of every error (no colours), one block each:
    ///
    /// ```text
    /// error: undeclared symbol `y`
    ///  --> a.lmx:2:16
    ///   |
    /// 2 | matrix A = [x, y]
    ///   |                ^ not declared
    ///   = help: declare it with `var y`
    /// ```
    pub fn render(&self) -> String {
        let mut out = String::new();
        for (i, e) in self.errors.iter().enumerate() {
            if i > 0 {
                out.push('\n');
            }
            out.push_str(&format!("error: {}\n", elide_long_numbers(&e.message)));
            self.snippet(&mut out, e.span, &e.label);
            for (span, label) in &e.related {
                out.push_str("note:\n");
                self.snippet(&mut out, *span, label);
            }
            if let Some(help) = &e.help {
                out.push_str(&format!("  = help: {}\n", elide_long_numbers(help)));
            }
        }
        out
    }

    fn snippet(&self, out: &mut String, span: Span, label: &str) {
        let text = self.source.inner();
        let (line, col) = line_col(text, span.start);
        let line_text = text.lines().nth(line - 1).unwrap_or("");
        let gutter = " ".repeat(line.to_string().len());
        let line_chars = line_text.chars().count();
        let span_chars = text
            .get(clamp(text, span.start)..clamp(text, span.end))
            .map_or(1, |s| s.chars().take_while(|c| *c != '\n').count());
        let width = span_chars
            .min(line_chars.saturating_sub(col - 1))
            .clamp(1, MAX_LINE_SHOWN / 2);
        let (shown, caret) = window(line_text, col);
        out.push_str(&format!(
            "{gutter}--> {}:{line}:{col}\n",
            self.source.name()
        ));
        out.push_str(&format!("{gutter} |\n"));
        out.push_str(&format!("{line} | {shown}\n"));
        out.push_str(&format!(
            "{gutter} | {}{} {}\n",
            " ".repeat(caret - 1),
            "^".repeat(width),
            elide_long_numbers(label)
        ));
    }
}

/// Longest run of digits shown in a message; longer numbers are elided.
pub const MAX_DIGITS_SHOWN: usize = 24;

/// Longest source line shown whole under an error; longer lines are cut
/// to a window around the caret.
pub const MAX_LINE_SHOWN: usize = 160;

/// `s` with every run of more than [`MAX_DIGITS_SHOWN`] digits shortened
/// to its first digits, `…` and its length, so that a pasted
/// 100 000-digit literal does not flood the terminal.
///
/// ```
/// use lambdamat::lang::diagnostics::elide_long_numbers;
/// let long = "7".repeat(1000);
/// assert_eq!(elide_long_numbers(&format!("x/{long}")), "x/777777777777…(1000 digits)");
/// assert_eq!(elide_long_numbers("x/12"), "x/12");
/// ```
pub fn elide_long_numbers(s: &str) -> String {
    let mut out = String::with_capacity(s.len().min(4096));
    let mut run = String::new();
    let flush = |run: &mut String, out: &mut String| {
        if run.len() > MAX_DIGITS_SHOWN {
            out.push_str(&run[..12]);
            out.push_str(&format!("…({} digits)", run.len()));
        } else {
            out.push_str(run);
        }
        run.clear();
    };
    for c in s.chars() {
        if c.is_ascii_digit() {
            run.push(c);
        } else {
            flush(&mut run, &mut out);
            out.push(c);
        }
    }
    flush(&mut run, &mut out);
    out
}

impl LangErrors {
    /// One [`LangErrors`] per error, each with the same source: a terminal
    /// renderer shows them one after another, each under its own heading.
    pub fn split(&self) -> Vec<LangErrors> {
        self.errors
            .iter()
            .map(|e| LangErrors {
                source: NamedSource::new(self.source.name(), self.source.inner().clone()),
                errors: vec![e.clone()],
            })
            .collect()
    }

    /// Whether a line shown under some error is longer than
    /// [`MAX_LINE_SHOWN`] characters (the terminal renderer then falls back
    /// to [`LangErrors::render`], which shows a window of it).
    ///
    /// Lines next to an error line count too, and so does a line with a
    /// number longer than [`MAX_DIGITS_SHOWN`] digits: the terminal
    /// renderer shows those lines as context, whole.
    pub fn has_long_lines(&self) -> bool {
        let text = self.source.inner();
        let long =
            |l: &str| l.chars().count() > MAX_LINE_SHOWN || elide_long_numbers(l).len() != l.len();
        self.errors
            .iter()
            .map(|e| e.span)
            .chain(
                self.errors
                    .iter()
                    .flat_map(|e| e.related.iter().map(|r| r.0)),
            )
            .any(|span| {
                let (line, _) = line_col(text, span.start);
                text.lines().skip(line.saturating_sub(2)).take(3).any(long)
            })
    }
}

/// The window of `line` shown under an error at character column `col`
/// (1-based) and the caret's column in it.
fn window(line: &str, col: usize) -> (String, usize) {
    let n = line.chars().count();
    if n <= MAX_LINE_SHOWN {
        return (line.to_string(), col);
    }
    let half = MAX_LINE_SHOWN / 2;
    let start = col.saturating_sub(half + 1);
    let end = (start + MAX_LINE_SHOWN).min(n);
    let mut shown: String = line.chars().skip(start).take(end - start).collect();
    let mut caret = col - start;
    if start > 0 {
        shown = format!("…{shown}");
        caret += 1;
    }
    if end < n {
        shown.push('…');
    }
    (shown, caret)
}

/// The largest char boundary not after `pos`.
fn clamp(text: &str, pos: usize) -> usize {
    let mut p = pos.min(text.len());
    while !text.is_char_boundary(p) {
        p -= 1;
    }
    p
}

/// 1-based line and character column of byte offset `pos` in `text`.
fn line_col(text: &str, pos: usize) -> (usize, usize) {
    let before = &text[..clamp(text, pos)];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let col = before[line_start..].chars().count() + 1;
    (line, col)
}

impl fmt::Display for LangErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.errors.as_slice() {
            [one] => write!(f, "{}", one.message),
            many => write!(f, "{} errors in {}", many.len(), self.source.name()),
        }
    }
}

impl std::error::Error for LangErrors {}

impl Diagnostic for LangErrors {
    fn code<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        None
    }

    fn source_code(&self) -> Option<&dyn SourceCode> {
        Some(&self.source)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        match self.errors.as_slice() {
            [one] => one.labels(),
            _ => None,
        }
    }

    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        match self.errors.as_slice() {
            [one] => one.help(),
            _ => None,
        }
    }

    fn related<'a>(&'a self) -> Option<Box<dyn Iterator<Item = &'a dyn Diagnostic> + 'a>> {
        if self.errors.len() > 1 {
            Some(Box::new(self.errors.iter().map(|e| e as &dyn Diagnostic)))
        } else {
            None
        }
    }
}

impl fmt::Display for LangError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.message)
    }
}

impl std::error::Error for LangError {}

impl Diagnostic for LangError {
    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let primary = LabeledSpan::new_primary_with_span(
            Some(self.label.clone()),
            (
                self.span.start,
                self.span.end.saturating_sub(self.span.start),
            ),
        );
        let related = self.related.iter().map(|(s, l)| {
            LabeledSpan::new_with_span(Some(l.clone()), (s.start, s.end.saturating_sub(s.start)))
        });
        Some(Box::new(std::iter::once(primary).chain(related)))
    }

    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.help
            .as_ref()
            .map(|h| Box::new(h.clone()) as Box<dyn fmt::Display>)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lang::error::ErrorKind;

    #[test]
    fn line_col_counts_characters_from_one() {
        let text = "ab\nκ1 x\n";
        assert_eq!(line_col(text, 0), (1, 1));
        assert_eq!(line_col(text, 3), (2, 1));
        // `x` comes after the two-byte `κ`, `1` and a blank.
        assert_eq!(line_col(text, text.find('x').unwrap_or(0)), (2, 4));
        assert_eq!(line_col(text, 1000), (3, 1));
    }

    #[test]
    fn render_shows_location_line_and_caret() {
        let text = "var x\nmatrix A = [x, y]\n";
        let at = text.find('y').unwrap_or(0);
        let e = LangError::new(
            ErrorKind::Undeclared,
            "undeclared symbol `y`",
            Span::new(at, at + 1),
            "not declared",
        )
        .with_help("declare it with `var y`");
        let errs = LangErrors::new("a.lmx", text, vec![e]);
        assert_eq!(
            errs.render(),
            "error: undeclared symbol `y`\n --> a.lmx:2:16\n  |\n2 | matrix A = [x, y]\n  |                ^ not declared\n  = help: declare it with `var y`\n"
        );
    }

    #[test]
    fn miette_renders_every_error() {
        let text = "var x\nmatrix A = [y, z]\n";
        let mk = |c: char| {
            let at = text.find(c).unwrap_or(0);
            LangError::new(
                ErrorKind::Undeclared,
                format!("undeclared symbol `{c}`"),
                Span::new(at, at + 1),
                "not declared",
            )
        };
        let errs = LangErrors::new("a.lmx", text, vec![mk('y'), mk('z')]);
        let mut out = String::new();
        miette::GraphicalReportHandler::new_themed(miette::GraphicalTheme::unicode_nocolor())
            .render_report(&mut out, &errs)
            .expect("render");
        assert!(out.contains("2 errors in a.lmx"), "{out}");
        assert!(out.contains("undeclared symbol `y`"), "{out}");
        assert!(out.contains("undeclared symbol `z`"), "{out}");
        assert!(out.contains("a.lmx:2:13"), "{out}");
    }
}
