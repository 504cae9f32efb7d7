//! Every formula the command line prints in `--json` is the value it stands
//! for: the tests read the printed text back with `lang::formula` and check
//! the mathematics from that text alone. The principal-mode Smith forms of
//! issue 14's matrix and of seeded random matrices are re-multiplied from
//! their printed U, D, V (against A read from the generated source, not
//! from the JSON), and the formulas of `smith --json` and `reduce --json`
//! on every example parse back.
mod common;

use common::cli::{json, lmx_file};
use lambdamat::algebra::ratfunc::{RatFunc, RatFuncField};
use lambdamat::algebra::ring::Ring;
use lambdamat::lang::formula::{parse_ncexpr, parse_ratfunc};
use serde_json::Value;

fn field(names: &[String]) -> RatFuncField {
    RatFuncField {
        names: names.to_vec(),
        shown: names.to_vec(),
    }
}

fn read(v: &Value, names: &[String]) -> RatFunc {
    let s = v.as_str().expect("a formula is a string");
    parse_ratfunc(s, names).unwrap_or_else(|e| panic!("`{s}` does not parse back: {}", e.render()))
}

fn matrix(v: &Value, names: &[String]) -> Vec<Vec<RatFunc>> {
    v.as_array()
        .expect("rows")
        .iter()
        .map(|r| {
            r.as_array()
                .expect("row")
                .iter()
                .map(|e| read(e, names))
                .collect()
        })
        .collect()
}

fn mul(k: &RatFuncField, a: &[Vec<RatFunc>], b: &[Vec<RatFunc>]) -> Vec<Vec<RatFunc>> {
    let inner = b.len();
    let cols = b.first().map_or(0, Vec::len);
    a.iter()
        .map(|row| {
            (0..cols)
                .map(|j| (0..inner).fold(k.zero(), |acc, t| k.add(&acc, &k.mul(&row[t], &b[t][j]))))
                .collect()
        })
        .collect()
}

/// Runs `smith --principal` on `entries` (rows of source text) and checks
/// U·A·V = D and the printed invariant factors from the printed text.
fn check_principal(names: &[&str], principal: &str, entries: &[Vec<String>]) {
    let names: Vec<String> = names.iter().map(|s| s.to_string()).collect();
    let rows: Vec<String> = entries.iter().map(|r| r.join(", ")).collect();
    let src = format!(
        "var {}\nmatrix A = [\n  {}\n]\nsmith A\n",
        names.join(", "),
        rows.join(";\n  ")
    );
    let f = lmx_file(&src);
    let path = f.path().to_str().expect("utf-8");
    let out = json(&["smith", path, "--principal", principal]);
    let k = field(&names);
    // A from the source we wrote, never from the printed JSON.
    let a: Vec<Vec<RatFunc>> = entries
        .iter()
        .map(|r| {
            r.iter()
                .map(|e| parse_ratfunc(e, &names).expect("source entry"))
                .collect()
        })
        .collect();
    let (u, d, v) = (
        matrix(&out["U"], &names),
        matrix(&out["D"], &names),
        matrix(&out["V"], &names),
    );
    let uav = mul(&k, &mul(&k, &u, &a), &v);
    for (i, row) in uav.iter().enumerate() {
        for (j, e) in row.iter().enumerate() {
            assert!(
                k.is_zero(&k.sub(e, &d[i][j])),
                "{src}\nprinted U·A·V ≠ printed D at ({i}, {j})"
            );
        }
    }
    let factors = out["invariant_factors"].as_array().expect("factors");
    for (i, f) in factors.iter().enumerate() {
        assert!(
            k.is_zero(&k.sub(&read(f, &names), &d[i][i])),
            "{src}\ninvariant factor {i} ≠ D[{i}][{i}]"
        );
    }
}

#[test]
fn issue_14_matrix_is_printed_as_its_value() {
    let e = |s: &str| s.to_string();
    check_principal(
        &["k1", "k4"],
        "k4",
        &[vec![e("k1 + 1"), e("k1*k4 + 1")], vec![e("k4^2"), e("k1")]],
    );
    // The factor itself, against det A = k1² + k1 − k1·k4³ − k4² made monic in k4.
    let f = lmx_file("var k1, k4\nmatrix A = [k1 + 1, k1*k4 + 1; k4^2, k1]\nsmith A\n");
    let out = json(&[
        "smith",
        f.path().to_str().expect("utf-8"),
        "--principal",
        "k4",
    ]);
    let names = vec!["k1".to_string(), "k4".to_string()];
    let k = field(&names);
    let printed = read(&out["invariant_factors"][1], &names);
    let expected = parse_ratfunc("k4^3 + k4^2/k1 - k1 - 1", &names).expect("valid");
    assert!(k.is_zero(&k.sub(&printed, &expected)));
}

/// A small deterministic generator (the test must not depend on a seed
/// source outside it).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self, n: u64) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 33) % n
    }
}

#[test]
fn random_principal_mode_forms_are_printed_as_their_values() {
    let mut g = Lcg(14);
    let monomials = ["1", "a", "b", "a*b", "b^2", "a^2"];
    let mut checked = 0;
    for case in 0..12 {
        let n = 2 + case % 2;
        let entries: Vec<Vec<String>> = (0..n)
            .map(|_| {
                (0..n)
                    .map(|_| {
                        let terms: Vec<String> = (0..1 + g.next(2))
                            .map(|_| {
                                let c = g.next(5) as i64 - 2;
                                let m = monomials[g.next(monomials.len() as u64) as usize];
                                format!("({c})*{m}")
                            })
                            .collect();
                        terms.join(" + ")
                    })
                    .collect()
            })
            .collect();
        check_principal(&["a", "b"], "b", &entries);
        checked += 1;
    }
    assert_eq!(checked, 12);
}

#[test]
fn json_formulas_of_every_example_parse_back() {
    let mut smith_checked = 0;
    let mut reduce_checked = 0;
    for entry in std::fs::read_dir("examples").expect("examples") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|e| e != "lmx") {
            continue;
        }
        let f = path.to_str().expect("utf-8");
        let text = std::fs::read_to_string(&path).expect("readable");
        let Ok(prog) = lambdamat::lang::parse_program(&text, f) else {
            continue;
        };
        let names = prog.symbols.clone();
        let out = common::cli::lambdamat()
            .args(["smith", f, "--json"])
            .output()
            .expect("runs");
        if out.status.success() {
            let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
            for key in ["A", "D"] {
                if !v[key].is_null() {
                    matrix(&v[key], &names);
                }
            }
            for fct in v["invariant_factors"].as_array().into_iter().flatten() {
                read(fct, &names);
            }
            smith_checked += 1;
        }
        if prog.unknowns.is_empty() || prog.contact.is_split() {
            continue;
        }
        let out = common::cli::lambdamat()
            .args(["reduce", f, "--json"])
            .output()
            .expect("runs");
        if !out.status.success() {
            // A singular λ-matrix (examples/singular.lmx) has no reduction.
            continue;
        }
        let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
        for row in v["lambda_matrix"].as_array().into_iter().flatten() {
            for e in row.as_array().into_iter().flatten() {
                read(e, &names);
            }
        }
        for fct in v["invariant_factors"].as_array().into_iter().flatten() {
            read(fct, &names);
        }
        let mut nc = vec![&v["eliminant"]["lhs_ordered"]];
        nc.extend(v["ordered_inverses"].as_array().into_iter().flatten());
        nc.extend(
            v["eliminant"]["dropped"]
                .as_array()
                .into_iter()
                .flatten()
                .map(|d| &d["operator"]),
        );
        for e in nc.into_iter().filter(|e| e.is_string()) {
            let s = e.as_str().expect("string");
            parse_ncexpr(s, &names)
                .unwrap_or_else(|err| panic!("{f}: `{s}` does not parse back: {}", err.render()));
        }
        // The ordered elimination as steps, over its own symbols
        // (operators, g1..gn, the named intermediates).
        let st = &v["ordered_steps"];
        let all: Vec<String> = st["symbols"]
            .as_array()
            .unwrap_or_else(|| panic!("{f}: no ordered_steps"))
            .iter()
            .map(|x| x.as_str().expect("name").to_string())
            .collect();
        let mut formulas = vec![&st["result"]["lhs"], &st["result"]["rhs"]];
        for step in st["steps"].as_array().into_iter().flatten() {
            formulas.extend([&step["pivot"], &step["inverse"]]);
            formulas.extend(
                step["updates"]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .map(|u| &u["value"]),
            );
        }
        for e in formulas {
            let s = e.as_str().expect("a formula is a string");
            parse_ncexpr(s, &all)
                .unwrap_or_else(|err| panic!("{f}: `{s}` does not parse back: {}", err.render()));
        }
        reduce_checked += 1;
    }
    assert!(
        smith_checked >= 2,
        "only {smith_checked} smith reports read"
    );
    assert!(reduce_checked >= 5, "only {reduce_checked} reductions read");
}
