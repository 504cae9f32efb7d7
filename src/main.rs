//! The `lambdamat` binary: a thin shell around [`lambdamat::cli_main`].
fn main() {
    std::process::exit(lambdamat::cli_main());
}
