//! `camber edit`: serve the interactive editor for one sketch file on this machine (see
//! [`crate::editor`] for the requests it answers and docs/cli.md for the page).

use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use crate::editor::server::Server;
use crate::editor::EditorState;

/// Arguments of `camber edit`.
#[derive(Debug, Args)]
pub struct EditArgs {
    /// The sketch file.
    pub input: PathBuf,
    /// The port to listen on; 0 picks a free one (printed on start).
    #[arg(long, default_value_t = 0)]
    pub port: u16,
    /// The address to listen on. Other machines can reach the editor only if this is not a
    /// loopback address; it has no password, so a non-loopback address also needs
    /// `--allow-remote`.
    #[arg(long, value_name = "ADDR", default_value_t = IpAddr::V4(Ipv4Addr::LOCALHOST))]
    pub bind: IpAddr,
    /// Allow a non-loopback `--bind` address: anyone who can reach it can edit and save the
    /// sketch, since the editor has no authentication.
    #[arg(long)]
    pub allow_remote: bool,
    /// Where "Save" writes the sketch (default: the input file itself).
    #[arg(short, long, value_name = "OUT.json")]
    pub output: Option<PathBuf>,
    /// Also open the editor in the default web browser.
    #[arg(long)]
    pub open: bool,
    /// Start from an empty sketch that "Save" writes to the input path (which must not exist
    /// yet).
    #[arg(long)]
    pub new: bool,
    /// Open the sketch as the file has it, without solving a sketch whose constraints do not
    /// all hold.
    #[arg(long)]
    pub no_solve: bool,
}

/// Loads the sketch, listens, prints the address, and answers requests until interrupted.
pub fn run(args: &EditArgs) -> Result<()> {
    if !args.bind.is_loopback() {
        if !args.allow_remote {
            anyhow::bail!(
                "--bind {}: not a loopback address, so other machines could edit and save the \
                 sketch without any password; add --allow-remote if that is intended",
                args.bind
            );
        }
        eprintln!(
            "camber edit: warning: listening on {}, reachable from other machines without \
             authentication",
            args.bind
        );
    }
    let mut state = if args.new {
        if args.input.exists() {
            anyhow::bail!(
                "{}: the file exists; open it without --new, or give a new name",
                args.input.display()
            );
        }
        EditorState::new(
            camber_sketch::Sketch::new(),
            args.input.clone(),
            args.output.clone(),
        )?
    } else {
        EditorState::load(&args.input, args.output.clone())?
    };
    if !args.no_solve {
        state.solve_on_open()?;
    }
    let server = Server::bind(SocketAddr::new(args.bind, args.port))?;
    let url = server.url();
    crate::print_stdout(&format!(
        "camber edit: {} at {url} (Ctrl-C to stop)",
        args.input.display()
    ))?;
    if args.open {
        if let Err(e) = open_browser(&url) {
            eprintln!("camber edit: could not open a browser ({e}); open {url} yourself");
        }
    }
    server.serve(&mut state)
}

/// Asks the desktop to open `url` in the default browser.
fn open_browser(url: &str) -> std::io::Result<()> {
    let mut command = if cfg!(target_os = "macos") {
        std::process::Command::new("open")
    } else if cfg!(windows) {
        let mut c = std::process::Command::new("cmd");
        c.args(["/C", "start", ""]);
        c
    } else {
        std::process::Command::new("xdg-open")
    };
    command
        .arg(url)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .map(|mut child| {
            // Reap the opener when it exits, so it does not linger as a zombie.
            std::thread::spawn(move || child.wait());
        })
}
