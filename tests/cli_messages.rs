//! Small things the command line must say right (issue 12's cosmetic
//! findings): matrices keep their own names, the LaTeX comment speaks
//! words, a system without symbols is over Q, defaults are shown as
//! written, and a file starting with a byte-order mark is read.

mod common;

use common::cli::{lambdamat, lmx_file, stdout};
use predicates::prelude::*;

#[test]
fn a_matrix_is_printed_under_its_own_name() {
    let f = lmx_file("matrix Z = [1, 2; 3, 4]\nsmith Z\n");
    let p = f.path().to_str().expect("utf-8");
    let text = stdout(&["run", p]);
    assert!(text.contains("Z = [ 1 , 2 ]"), "{text}");
    assert!(!text.contains("\nA = ["), "{text}");
    let latex = stdout(&["run", p, "--latex"]);
    assert!(latex.contains("\\[ Z = "), "{latex}");
    assert!(
        !latex.contains("OneSymbol") && !latex.contains("mode)"),
        "{latex}"
    );
}

#[test]
fn a_system_without_symbols_is_over_q() {
    let f = lmx_file("unknown p\nequation 2*p = 1\n");
    let text = stdout(&["reduce", f.path().to_str().expect("utf-8")]);
    assert!(text.contains("λ-matrix over Q "), "{text}");
    assert!(!text.contains("Q[]"), "{text}");
}

#[test]
fn defaults_are_shown_as_written() {
    for args in [
        &["solve", "--help"][..],
        &["hertz", "--help"],
        &["hertz", "sweep", "--help"],
    ] {
        lambdamat()
            .args(args)
            .assert()
            .success()
            .stdout(predicate::str::contains("0.0000").not())
            .stdout(predicate::str::contains("[default: 1e-"));
    }
}

#[test]
fn a_byte_order_mark_is_ignored() {
    let f = lmx_file("\u{feff}var x\nmatrix A = [x, 1]\nsmith A\n");
    let text = stdout(&["run", f.path().to_str().expect("utf-8")]);
    assert!(text.contains("Smith normal form of A over Q[x]"), "{text}");
}
