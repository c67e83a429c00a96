//! The `cyclecheck` binary: its command line is [`cli`]; what the commands run is the
//! `cyclecheck` library and the kernel (`cycle_kernel`).

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
