//! The `lambdamat` binary: a thin shell around [`lambdamat::cli::main`].
fn main() {
    std::process::exit(lambdamat::cli::main());
}
