//! The `lancer` command: renders POV-Ray scenes. Exit codes: 0 success, 1 scene or output
//! error, 2 usage error. The work is `lancer::app::run`, shared with the Python module.

fn main() -> std::process::ExitCode {
    lancer::app::run_main(std::env::args().collect())
}
