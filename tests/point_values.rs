//! Point values `p(c)` in outputs through the command line: on a
//! split-domain problem (the manufactured Hertz-type problem of
//! `examples/hertz_split_mms.lmx`, exact p = x, q = 4x³ in the stick zone
//! [0, 1/2) and q = p in the slip zone), where a point value reads the free
//! part, the substituted part or the exact singular terms of an unknown.

mod common;

use common::cli::json;

#[test]
fn point_values_on_a_split_domain() {
    let base = std::fs::read_to_string("examples/hertz_split_mms.lmx").expect("example");
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("split_points.lmx");
    std::fs::write(
        &path,
        format!("{base}\noutput PA = p(1/4)\noutput QB = q(1/4)\noutput QC = q(3/4) - 2*p(3/4)\n"),
    )
    .expect("write");
    let v = json(&["solve", path.to_str().expect("utf-8 path")]);
    assert_eq!(v["converged"], true);
    let out = |name: &str| v["outputs"][name].as_f64().expect(name);
    // p(1/4) = 1/4; q(1/4) = 4/64 in the stick zone; in the slip zone
    // q(3/4) = p(3/4) = 3/4, so q(3/4) - 2 p(3/4) = -3/4.
    for (name, exact) in [("PA", 0.25), ("QB", 1.0 / 16.0), ("QC", -0.75)] {
        let err = (out(name) - exact).abs();
        assert!(err < 1e-10, "{name} = {} (error {err:e})", out(name));
    }
}
