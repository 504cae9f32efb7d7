//! Regression tests for inputs that used to stall the Smith engine (issue
//! 15), kept small enough to run in seconds: the principal-mode 4×4 in
//! three symbols that spent minutes in the rational-coefficient PRS gcd,
//! a 2×2 of degree 100 over Q[x] (now one Bezout identity by a modular
//! inverse), and a 9×9 in two symbols whose minors are too many to enumerate
//! (the determinantal mode then goes through one Smith form per symbol);
//! and the large one-symbol shapes: a constant 60×60 (unimodular path), a
//! 40×40 diagonal and a dense 40×40 of degree 1 (invariant factors
//! certified without transforms), and a 12×12 B·diag·C with two
//! non-trivial invariant factors (Hermite basis, with transforms); and the
//! several-symbol inputs certified from det and adj without elimination
//! or minors (a 10×10 over Q[x, y], a random 4×4 over Q[x, y, z]); and a
//! 24×24 with three non-trivial factors certified without transforms, the
//! issue's 50×50 of degree 1 without the adjugate; a 4×4 of 45-digit
//! rationals against PARI's factor (issue 29).

mod common;

use common::cli::json;
use serde_json::Value;

fn strings(v: &Value) -> Vec<String> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|s| s.as_str().expect("string").to_string())
        .collect()
}

#[test]
fn principal_k2_four_by_four_in_three_symbols() {
    let v = json(&[
        "smith",
        "tests/data/issue15_principal_k2.lmx",
        "--principal",
        "k2",
    ]);
    assert_eq!(v["mode"], "principal");
    assert_eq!(v["ring"], "Q(k1, k3)[k2]");
    assert_eq!(v["verified"], true);
    assert_eq!(v["denominator_free"]["verified"], true);
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), 4);
    assert_eq!(&inv[..3], ["1", "1", "1"]);
    // The last factor is monic in k2 of degree 4 (det A has k2-degree 4
    // after removing its content in Q[k1, k3]).
    assert!(inv[3].starts_with("k2^4"), "{}", inv[3]);
}

#[test]
fn principal_and_determinantal_modes_agree_on_the_four_by_four() {
    // Over Q[k1, k2, k3] (minors) and over Q(k1, k3)[k2]: the k2-primitive
    // part of the last determinantal divisor is the last D′ entry.
    let det = json(&["smith", "tests/data/issue15_principal_k2.lmx"]);
    assert_eq!(det["verified"], true);
    let p = json(&[
        "smith",
        "tests/data/issue15_principal_k2.lmx",
        "--principal",
        "k2",
    ]);
    let f4 = strings(&det["invariant_factors"])[3].clone();
    let d4 = p["denominator_free"]["D"][3][3]
        .as_str()
        .expect("entry")
        .to_string();
    let c4 = p["denominator_free"]["C"][3]
        .as_str()
        .expect("entry")
        .to_string();
    assert!(!d4.is_empty() && !c4.is_empty());
    // f4 = k3·D′ here: D′ is f4 without its content k3 in Q[k1, k3]. Check
    // term by term: appending k3 to each term of D′ gives f4's terms.
    let times_k3 = |t: &str| -> String {
        let t = t.trim();
        match t.rfind("k3") {
            Some(i) if t[i..].starts_with("k3^") => {
                let e: u32 = t[i + 3..].parse().expect("exponent");
                format!("{}k3^{}", &t[..i], e + 1)
            }
            Some(i) => format!("{}k3^2{}", &t[..i], &t[i + 2..]),
            None => format!("{t}*k3"),
        }
    };
    let terms = |s: &str| -> Vec<String> {
        s.replace(" - ", " + -")
            .split(" + ")
            .map(|t| t.trim().to_string())
            .collect()
    };
    let shifted: Vec<String> = terms(&d4).iter().map(|t| times_k3(t)).collect();
    assert_eq!(shifted, terms(&f4), "D′ = {d4}, f4 = {f4}");
}

#[test]
fn qx_two_by_two_of_degree_100_takes_the_bezout_route() {
    // One Bezout identity on the first row (modular inverse, early
    // termination proved by exact division); U·A·V = D certified.
    let v = json(&["smith", "tests/data/issue15_qx_2x2_deg100.lmx"]);
    assert_eq!(v["mode"], "one-symbol");
    assert_eq!(v["verified"], true);
    assert!(
        v["algorithm"]
            .as_str()
            .expect("text")
            .starts_with("2×2 with a coprime first row"),
        "{}",
        v["algorithm"]
    );
    assert!(v["U"].is_array() && v["V"].is_array());
    let names = check_names(&v);
    for want in ["U·A·V = D", "U unimodular", "V unimodular"] {
        assert!(names.iter().any(|n| n == want), "{want} missing: {names:?}");
    }
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv[0], "1");
    assert!(inv[1].starts_with("x^200"), "degree 200 expected");
}

#[test]
fn determinantal_mode_without_minors_on_a_planted_nine_by_nine() {
    let v = json(&["smith", "tests/data/issue15_xy_9x9_planted.lmx"]);
    assert_eq!(v["mode"], "determinantal-divisors");
    assert_eq!(v["verified"], true);
    assert!(
        v["algorithm"]
            .as_str()
            .expect("text")
            .starts_with("lcm over each symbol"),
        "{}",
        v["algorithm"]
    );
    let mut want = vec!["1"; 7];
    want.extend(["x + y", "x^2 + x*y"]);
    assert_eq!(strings(&v["invariant_factors"]), want);
    // Each symbol's Smith form was certified.
    let cert = v["certificate"].as_array().expect("checks");
    assert!(
        cert.iter()
            .filter(|c| c["property"]
                .as_str()
                .is_some_and(|p| p.starts_with("Smith form over")))
            .count()
            == 2
    );
}

#[test]
fn constant_sixty_by_sixty_goes_through_the_unimodular_path() {
    // A nonsingular constant matrix: D = I, U = I/det, V = adj (integer),
    // det and adj from images mod word primes; certified like any other.
    let v = json(&["smith", "tests/data/issue15_const_60.lmx"]);
    assert_eq!(v["verified"], true);
    assert!(
        v["algorithm"]
            .as_str()
            .expect("text")
            .starts_with("nonsingular path"),
        "{}",
        v["algorithm"]
    );
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv, vec!["1"; 60]);
    assert!(v["U"].is_array() && v["V"].is_array());
    // U is a scalar matrix: off-diagonal entries are 0.
    assert_eq!(v["U"][0][1], "0");
}

/// `smith FILE --json` of an n×n input with `nontrivial` planted
/// non-trivial factors: verified, with U and V and their certificate
/// lines, invariant factors 1, …, 1 then the rest; returns the JSON and
/// the factors.
fn certified_with_transforms(file: &str, n: usize, nontrivial: usize) -> (Value, Vec<String>) {
    let v = json(&["smith", file]);
    assert_eq!(v["verified"], true);
    assert!(v["U"].is_array() && v["V"].is_array());
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), n);
    assert!(inv[..n - nontrivial].iter().all(|f| f == "1"), "{inv:?}");
    let names = check_names(&v);
    for want in ["U·A·V = D", "U unimodular", "V unimodular"] {
        assert!(names.iter().any(|n| n == want), "{want} missing: {names:?}");
    }
    (v, inv)
}

fn check_names(v: &Value) -> Vec<String> {
    v["certificate"]
        .as_array()
        .expect("checks")
        .iter()
        .map(|c| {
            assert_eq!(c["ok"], true, "{c}");
            c["property"].as_str().expect("name").to_string()
        })
        .collect()
}

#[test]
fn large_diagonal_gets_certified_invariant_factors_without_transforms() {
    let v = json(&["smith", "tests/data/issue15_diag_40.lmx"]);
    assert_eq!(v["mode"], "one-symbol");
    assert_eq!(v["verified"], true);
    assert!(v["U"].is_null() && v["V"].is_null());
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), 40);
    assert!(inv[..39].iter().all(|f| f == "1"));
    // Π_(i=1..40) (x − i) = x^40 − 820·x^39 + …
    assert!(inv[39].starts_with("x^40 - 820*x^39 + "), "{}", inv[39]);
    let names = check_names(&v);
    for want in [
        "A·B = c·I",
        "gcd of the entries of B is 1",
        "deg c = degree bound of det A",
        "invariant factors 1, …, 1, f",
    ] {
        assert!(names.iter().any(|n| n == want), "{want} missing: {names:?}");
    }
    assert!(
        v["mode_note"]
            .as_str()
            .expect("text")
            .contains("transforms omitted")
    );
}

#[test]
fn forty_by_forty_of_degree_one_certifies_the_form_when_transforms_are_huge() {
    let v = json(&["smith", "tests/data/issue15_qx_40x40_deg1.lmx"]);
    assert_eq!(v["verified"], true);
    assert!(v["U"].is_null());
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), 40);
    assert!(inv[..39].iter().all(|f| f == "1"));
    assert!(inv[39].starts_with("x^40"), "{}", inv[39]);
    assert_eq!(check_names(&v).len(), 4);
    assert!(
        v["mode_note"]
            .as_str()
            .expect("text")
            .contains("transforms omitted: U would hold about")
    );
}

#[test]
fn two_nontrivial_factors_get_certified_transforms() {
    // B·diag(1, …, 1, x − 1, (x − 1)(x + 2))·C with B, C dense random of
    // degree 1 (12×12): d_(n−1) = x − 1, so the single-factor Hermite
    // shortcut declines; the Hermite basis is glued by CRT from the
    // rank-one part of adj and an HNF modulo (x − 1)², and U·A·V = D is
    // certified as usual. The expected last factor was produced by the
    // general elimination with transforms (certified U·A·V = D), before
    // either shortcut existed.
    let (v, inv) = certified_with_transforms("tests/data/issue15_bdc_12.lmx", 12, 2);
    assert_eq!(inv[10], "x - 1");
    let want = std::fs::read_to_string("tests/data/issue15_bdc_12_f12.txt").expect("data");
    assert_eq!(inv[11], want.trim());
    assert!(
        v["algorithm"]
            .as_str()
            .expect("text")
            .contains("Hermite basis")
    );
}

#[test]
fn ten_by_ten_in_two_symbols_in_both_several_symbol_modes() {
    // Used to run for minutes in either mode (elimination over Q(x)[y],
    // and over Q(y)[x] and Q(x)[y] for the divisors); now det and adj by
    // Kronecker packing, certified from A·B = c·I.
    let file = "tests/data/issue15_xy_10x10.lmx";
    let det = json(&["smith", file]);
    assert_eq!(det["mode"], "determinantal-divisors");
    assert_eq!(det["verified"], true);
    let inv = strings(&det["invariant_factors"]);
    assert_eq!(inv.len(), 10);
    assert!(inv[..9].iter().all(|f| f == "1"));
    // Each symbol was certified (degree and coprimality checks).
    let props: Vec<String> = det["certificate"]
        .as_array()
        .expect("checks")
        .iter()
        .map(|c| c["property"].as_str().expect("text").to_string())
        .collect();
    for s in ["x", "y"] {
        assert!(props.contains(&format!("deg_{s} c = degree bound of det A")));
        assert!(props.contains(&format!("gcd of B's entries over Q(others)[{s}] is 1")));
    }
    for p in ["x", "y"] {
        let v = json(&["smith", file, "--principal", p]);
        assert_eq!(v["mode"], "principal");
        assert_eq!(v["verified"], true);
        assert!(v["U"].is_null() && v["denominator_free"].is_null());
        let pinv = strings(&v["invariant_factors"]);
        assert_eq!(pinv.len(), 10);
        assert!(pinv[..9].iter().all(|f| f == "1"));
        // Monic of degree 10 in the principal symbol.
        assert!(pinv[9].starts_with(&format!("{p}^10")), "{}", pinv[9]);
        // Cleared of denominators it is the last determinantal divisor.
        let note = v["mode_note"].as_str().expect("text");
        assert!(note.ends_with(&format!("is {}", inv[9])), "{note}");
    }
}

#[test]
fn random_four_by_four_in_three_symbols_in_both_modes() {
    // One of the seeded random 2×2–4×4 inputs whose principal-mode
    // elimination over Q(x, y)[z] ran for more than 10 s (det of 180
    // terms); the determinantal mode used gcds of minors.
    let file = "tests/data/issue15_xyz_4x4_random.lmx";
    let det = json(&["smith", file]);
    assert_eq!(det["verified"], true);
    let inv = strings(&det["invariant_factors"]);
    assert_eq!(&inv[..3], ["1", "1", "1"]);
    let p = json(&["smith", file, "--principal", "z"]);
    assert_eq!(p["mode"], "principal");
    assert_eq!(p["verified"], true);
    let pinv = strings(&p["invariant_factors"]);
    assert_eq!(&pinv[..3], ["1", "1", "1"]);
    assert!(pinv[3].starts_with("z^"), "{}", pinv[3]);
    let note = p["mode_note"].as_str().expect("text");
    assert!(note.contains("det A has 180 terms"), "{note}");
    assert!(note.ends_with(&format!("is {}", inv[3])), "{note}");
}

#[test]
fn three_nontrivial_factors_get_certified_transforms() {
    // B·diag(1, …, 1, x − 1, (x − 1)(x + 2), (x − 1)(x + 2)x)·C, 10×10, B of
    // degree 1 and C of degree 1 (benches/peers_grid.py, shape bdc3, seed 1):
    // the HNF modulo the repeated part (x − 1)³(x + 2)² has a 3×3 trailing
    // block. The first two non-trivial factors are the planted ones; the
    // last is det A over the two (monic), of degree deg det − 3.
    let (_, inv) = certified_with_transforms("tests/data/issue15_bdc3_10.lmx", 10, 3);
    assert_eq!(inv[7], "x - 1");
    assert_eq!(inv[8], "x^2 + x - 2");
    assert!(inv[9].starts_with("x^23 "), "{}", inv[9]);
}

#[test]
fn three_nontrivial_factors_certified_without_transforms_at_24() {
    // The bdc3 shape at 24×24: transforms would be huge (the Hermite-basis
    // route with U, V took 109 s at 32×32), so D alone is certified from
    // A·B = c·I: f_n = c/gcd(B), deg det A modulo a prime, and the Smith
    // form of the 3×3 trailing block of a Hermite basis modulo the
    // repeated part, with L(A) ⊆ L(H) and the degrees adding up.
    let v = json(&["smith", "tests/data/issue15_bdc3_24.lmx"]);
    assert_eq!(v["verified"], true);
    assert!(v["U"].is_null() && v["V"].is_null());
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), 24);
    assert!(inv[..21].iter().all(|f| f == "1"), "{inv:?}");
    assert_eq!(inv[21], "x - 1");
    assert_eq!(inv[22], "x^2 + x - 2");
    // deg det A = 24·1 (B) + 1 + 2 + 3 (chain) + 24·1 (C) = 54, minus 3.
    assert!(inv[23].starts_with("x^51 "), "{}", inv[23]);
    let names = check_names(&v);
    for want in [
        "A·B = c·I",
        "f_n = c/gcd(B)",
        "deg det A = D",
        "Smith form of the trailing block T",
        "L(A) ⊆ L(H)",
    ] {
        assert!(names.iter().any(|n| n == want), "{want} missing: {names:?}");
    }
}

#[test]
fn fifty_by_fifty_of_degree_one_without_the_adjugate() {
    // The issue's 50×50 row (> 180 s and 892 MB at first): from 48×48 on
    // a generic input gets det by images and two coprime (n−1)-minors.
    let v = json(&["smith", "tests/data/issue15_qx_50x50_deg1.lmx"]);
    assert_eq!(v["verified"], true);
    assert!(v["U"].is_null());
    assert!(
        v["algorithm"]
            .as_str()
            .expect("text")
            .contains("two (n−1)-minors coprime"),
        "{}",
        v["algorithm"]
    );
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), 50);
    assert!(inv[..49].iter().all(|f| f == "1"));
    assert!(inv[49].starts_with("x^50 "), "{}", inv[49]);
    let names = check_names(&v);
    assert!(names.iter().any(|n| n == "d_(n−1)(A) = 1"), "{names:?}");
}

#[test]
fn principal_k2_four_by_four_fraction_free_and_certified_by_degrees() {
    // The issue's 4×4 with --principal k2 goes through the fraction-free
    // elimination over Q[k1, k3][k2] and the degree certificate (no inverse
    // products). The last invariant factor is the one PARI's matsnf(M, 3)
    // gives over Q(k1, k3)[k2] (x^4 + ((a1^3 - 3*a1^2 + (-a3 + 2)*a1 -
    // 1)/a1)*x^3 + …, read off by hand).
    let v = json(&[
        "smith",
        "tests/data/issue15_principal_k2.lmx",
        "--principal",
        "k2",
    ]);
    assert_eq!(v["verified"], true);
    assert_eq!(v["denominator_free"]["verified"], true);
    assert!(
        v["algorithm"]
            .as_str()
            .expect("text")
            .starts_with("fraction-free elimination over Q[others][λ]"),
        "{}",
        v["algorithm"]
    );
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(
        inv[3],
        "k2^4 + ((k1^3 - 3*k1^2 - k1*k3 + 2*k1 - 1)/k1)*k2^3 + (k1*k3 - k3 + 1)*k2^2 - ((k1^3*k3^2 + k1^3*k3 - k1^3 - 2*k1^2*k3^2 - 3*k1^2*k3 + 3*k1^2 + 2*k1*k3^2 + 2*k1*k3 - 2*k1 - k3^2 - k3 + 1)/k1)*k2"
    );
    let checks = v["certificate"].as_array().expect("checks");
    let find = |p: &str| {
        checks
            .iter()
            .find(|c| c["property"] == p)
            .unwrap_or_else(|| panic!("no check {p}"))
    };
    for p in [
        "U·A·V = D",
        "U unimodular",
        "V unimodular",
        "divisibility f1 | f2 | …",
    ] {
        assert_eq!(find(p)["ok"], true, "{p}");
    }
    let detail = find("U unimodular")["detail"].as_str().expect("text");
    assert!(detail.contains("deg_k2 det A ≥ 4"), "{detail}");
    assert!(
        !checks
            .iter()
            .any(|c| c["detail"].as_str().unwrap_or("").contains("U⁻¹"))
    );
}

#[test]
fn non_square_with_zero_entries_is_certified() {
    // Found by timing the property-test strategies over many seeds: the
    // one-symbol certificate's product over Z[x] indexed past its
    // accumulator when a row entry was zero (exit 101 before the fix).
    let v = json(&["smith", "tests/data/smith_zero_entry_3x2.lmx"]);
    assert_eq!(v["mode"], "one-symbol");
    assert_eq!(v["verified"], true);
    assert_eq!(v["rank"], 2);
    assert_eq!(strings(&v["invariant_factors"]), ["1", "1"]);
}

#[test]
fn principal_non_square_inputs_whose_elimination_swells() {
    // Found by timing the printing tests' polynomial distribution as
    // matrix entries: the fraction-free elimination's remainder sequence
    // swelled (×11 in one round) and ran for minutes; the invariant factors
    // now come from the 2×2 minors, without transforms.
    for (f, sym, want) in [
        (
            "tests/data/issue15_principal_2x3_swell.lmx",
            "k4",
            ["1", "1"],
        ),
        (
            "tests/data/issue15_principal_2x3_swell.lmx",
            "k1",
            ["1", "k1"],
        ),
        (
            "tests/data/issue15_principal_3x2_swell.lmx",
            "k4",
            ["1", "k4^2"],
        ),
        (
            "tests/data/issue15_principal_3x2_swell.lmx",
            "k1",
            ["1", "1"],
        ),
    ] {
        let v = json(&["smith", f, "--principal", sym]);
        assert_eq!(v["mode"], "principal", "{sym}");
        assert_eq!(v["verified"], true, "{sym}");
        assert_eq!(v["rank"], 2, "{sym}");
        assert!(v["U"].is_null() && v["V"].is_null(), "{sym}");
        assert_eq!(strings(&v["invariant_factors"]), want, "{sym}");
        let note = v["mode_note"].as_str().expect("text");
        assert!(note.contains("safeguard"), "{note}");
    }
}

#[test]
fn principal_six_by_six_whose_det_is_below_the_degree_bound() {
    // The peers' grid 6×6 over Q[x, y] of degree 3 (seed 1): --principal y
    // stalled (over 60 s CPU) in the elimination over Q(x)[y]; now certified
    // from A·B = c·I with c/det A free of y by Jacobi's identity, D alone.
    use lambdamat::algebra::mpoly::MPoly;
    use lambdamat::algebra::ratfunc::{RatFunc, RatFuncField};
    use lambdamat::algebra::ring::Ring;
    use lambdamat::lang::formula::{parse_poly, parse_ratfunc};
    let file = "tests/data/issue15_principal_grid_6x6.lmx";
    let v = json(&["smith", file, "--principal", "y"]);
    assert_eq!(v["mode"], "principal");
    assert_eq!(v["ring"], "Q(x)[y]");
    assert_eq!(v["verified"], true);
    assert!(v["U"].is_null() && v["V"].is_null());
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), 6);
    assert_eq!(&inv[..5], ["1", "1", "1", "1", "1"]);
    // Independently: the determinantal mode's factors over Q[x, y] (gcd of
    // k×k minors) give d_5 and d_6 there; over Q(x)[y] the divisors are
    // their primitive parts in y (Gauss's lemma).
    let det = json(&["smith", file]);
    assert_eq!(det["verified"], true);
    let names = vec!["x".to_string(), "y".to_string()];
    let fd: Vec<MPoly> = strings(&det["invariant_factors"])
        .iter()
        .map(|s| parse_poly(s, &names).expect("polynomial"))
        .collect();
    assert_eq!(fd.len(), 6);
    let d5 = fd[..5].iter().fold(MPoly::one(2), |acc, f| &acc * f);
    // d_5 over Q[x, y] is free of y: a unit of Q(x)[y], so d_5 = 1 there.
    assert!(!d5.contains_var(1), "d_5 = {d5:?}");
    let d6 = &d5 * &fd[5];
    // f_6 = d_6/d_5 over Q(x)[y] = d_6 made monic in y.
    let lc = d6.coeffs_in(1).pop().expect("nonzero");
    let k = RatFuncField {
        names: names.clone(),
        shown: names.clone(),
    };
    let f6 = parse_ratfunc(&inv[5], &names).expect("rational function");
    let lhs = k.mul(&f6, &RatFunc::from_poly(lc));
    assert!(k.is_zero(&k.sub(&lhs, &RatFunc::from_poly(d6))));
    assert!(inv[5].starts_with("y^16 "), "{}", &inv[5][..40]);
    let note = v["mode_note"].as_str().expect("text");
    assert!(note.contains("transforms omitted"), "{note}");
}

#[test]
fn rectangular_and_rank_deficient_inputs_get_unit_factors_with_their_rank() {
    // 16×19 dense of degree 2 (rank 16) and B·C with B 16×12, C 12×16
    // (rank 12), seeded by benches/stall_families.py. Their maximal minors
    // are coprime, so every nonzero invariant factor is 1.
    for (file, rows, cols, rank) in [
        ("tests/data/issue29_rect_16x19_d2.lmx", 16, 19, 16),
        ("tests/data/issue29_rankdef_16_d1.lmx", 16, 16, 12),
    ] {
        let v = json(&["smith", file]);
        assert_eq!(v["verified"], true);
        assert!(v["U"].is_null(), "{file}");
        let inv = strings(&v["invariant_factors"]);
        assert_eq!(inv.len(), rank, "{file}");
        assert!(inv.iter().all(|f| f == "1"), "{file}: {inv:?}");
        let d = v["D"].as_array().expect("rows");
        assert_eq!((d.len(), d[0].as_array().expect("row").len()), (rows, cols));
        let names = check_names(&v);
        assert!(names.iter().any(|n| n == "rank A ≥ r and d_r(A) = 1"));
        assert_eq!(
            names.iter().any(|n| n == "rank A ≤ r"),
            rank < rows.min(cols)
        );
    }
}

#[test]
fn sparse_input_with_two_factors_is_certified_without_elimination_of_a() {
    // 24×24: random degree-1 diagonal plus 24 entries; PARI's matsnf gives
    // the factors x − 1 and one of degree 22 (the diagonal shares roots).
    let v = json(&["smith", "tests/data/issue29_sparse_24_e24.lmx"]);
    assert_eq!(v["verified"], true);
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), 24);
    assert!(inv[..22].iter().all(|f| f == "1"), "{inv:?}");
    assert_eq!(inv[22], "x - 1");
    assert!(inv[23].starts_with("x^22 "), "{}", inv[23]);
    check_names(&v);
}

#[test]
fn sparse_degree_two_input_is_certified_without_a_swelling_local_basis() {
    // 24×24 of degree 2: random diagonal plus 24 entries
    // (`issue29_sparse_24_e24_d2`, seeded in benches/stall_families.py).
    // PARI's matsnf did not answer within 20 s here and Singular's smith
    // disagrees on these sparse inputs (as on `issue29_sparse_24_e24`), so
    // no stored peer factors: the check is the certificate (A·B = c·I,
    // gcd(B), deg det A, L(A) ⊆ L(H)) and the factors' degrees summing to
    // deg det A (46). The trailing route now takes the gcd of all of B's
    // entries, so its local modulus has degree 2, not 35, and declines
    // quickly instead of running the Hermite basis over Q for minutes.
    let v = json(&["smith", "tests/data/issue29_sparse_24_e24_d2.lmx"]);
    assert_eq!(v["verified"], true);
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), 24);
    assert!(inv[..22].iter().all(|f| f == "1"), "{inv:?}");
    assert_eq!(inv[22], "x - 2/5");
    assert!(inv[23].starts_with("x^45 "), "{}", inv[23]);
    check_names(&v);
}

/// `f` printed the way the report prints a Q\[x\] polynomial, from its
/// coefficients (constant first) as PARI prints them.
fn printed_from_coefficients(coefs: &[&str]) -> String {
    let mut out = String::new();
    for (k, c) in coefs.iter().enumerate().rev() {
        if *c == "0" {
            continue;
        }
        let (neg, a) = c.strip_prefix('-').map_or((false, *c), |a| (true, a));
        let mono = match k {
            0 => String::new(),
            1 => "x".to_string(),
            _ => format!("x^{k}"),
        };
        let term = if k == 0 {
            a.to_string()
        } else if a == "1" {
            mono
        } else {
            format!("{a}*{mono}")
        };
        if out.is_empty() {
            out = if neg { format!("-{term}") } else { term };
        } else {
            out += if neg { " - " } else { " + " };
            out += &term;
        }
    }
    out
}

/// The n invariant factors of the report `v` are 1, …, 1 and PARI's
/// factor of degree `degree` made monic (`tests/data/CASE.pari`,
/// coefficients constant first).
fn last_factor_is_paris(v: &Value, case: &str, n: usize, degree: usize) {
    let inv = strings(&v["invariant_factors"]);
    assert_eq!(inv.len(), n);
    assert!(inv[..n - 1].iter().all(|f| f == "1"), "{inv:?}");
    let pari = std::fs::read_to_string(format!("tests/data/{case}.pari")).expect("PARI factor");
    let coefs: Vec<&str> = pari.lines().map(str::trim).collect();
    assert_eq!(coefs.len(), degree + 1);
    assert_eq!(inv[n - 1], printed_from_coefficients(&coefs));
}

#[test]
fn sixty_digit_rationals_give_the_certified_factors_alone() {
    // 6×6 of degree 2 with 60-digit rationals (`issue29_bigq_6_d2`, seeded
    // in benches/stall_families.py): det Ã has coefficients of about
    // 21 000 bits, so U's rows would need about 6 900 word primes, beyond
    // the modular route's supply, and the exact route stalled (over 60 s).
    // The invariant factors come alone, certified, and the note says why.
    // The factor of degree 12 is PARI's `matsnf(M, 2)` made monic
    // (`issue29_bigq_6_d2.pari`, coefficients constant first).
    let v = json(&["smith", "tests/data/issue29_bigq_6_d2.lmx"]);
    assert_eq!(v["verified"], true);
    assert!(v["U"].is_null() && v["V"].is_null(), "{}", v["U"]);
    let note = v["mode_note"].as_str().expect("note");
    assert!(note.contains("word primes to reconstruct"), "{note}");
    last_factor_is_paris(&v, "issue29_bigq_6_d2", 6, 12);
    let names = check_names(&v);
    assert!(names.iter().any(|n| n == "A·B = c·I"), "{names:?}");
}

#[test]
fn large_rational_four_by_four_matches_pari() {
    // 4×4 of degree 2 with 45-digit rational coefficients
    // (`issue29_bigq_4_d2`, seeded in benches/stall_families.py). Its row
    // scales give det Ã about 7 000 bits, so h needs about 1 500 word
    // primes: the integer Hermite route now takes them (`long_primes`)
    // instead of falling back to the exact extended Euclid over Q. The
    // factor of degree 8 is PARI's `matsnf(M, 2)` made monic
    // (`issue29_bigq_4_d2.pari`, coefficients constant first).
    let v = json(&["smith", "tests/data/issue29_bigq_4_d2.lmx"]);
    assert_eq!(v["verified"], true);
    assert!(v["U"].is_array() && v["V"].is_array());
    last_factor_is_paris(&v, "issue29_bigq_4_d2", 4, 8);
    let names = check_names(&v);
    for want in ["U·A·V = D", "U unimodular", "V unimodular"] {
        assert!(names.iter().any(|n| n == want), "{want} missing: {names:?}");
    }
}
