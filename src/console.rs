//! Where the `ffvk` command prints. Every line for stdout goes through [`write`] (the
//! [`outln!`](crate::outln) and [`out!`](crate::out) macros), which flushes it and turns a
//! failed write (a full disk, `> /dev/full`) into [`Error::Stdout`](crate::Error::Stdout),
//! where `println!` would panic. Messages for stderr go through [`note`] (the
//! [`errln!`](crate::errln) macro), which drops a failed write: there is nowhere left to say
//! it. A closed pipe (`ffvk info | head -1`) ends the process through SIGPIPE before a write
//! can fail (the command restores that signal's default), as it ends other Unix tools.

use std::io::Write;

/// Writes `args` to stdout and flushes it, so that a failure shows here and not in an exit
/// that cannot report it.
pub fn write(args: std::fmt::Arguments<'_>) -> crate::Result<()> {
    let mut stdout = std::io::stdout().lock();
    stdout
        .write_fmt(args)
        .and_then(|()| stdout.flush())
        .map_err(crate::Error::Stdout)
}

/// Writes `args` to stderr; a failed write is dropped.
pub fn note(args: std::fmt::Arguments<'_>) {
    let _ = std::io::stderr().lock().write_fmt(args);
}

/// `println!` that returns a failed write as [`Error::Stdout`](crate::Error::Stdout).
#[macro_export]
macro_rules! outln {
    () => {
        $crate::console::write(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::console::write(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// `print!` that returns a failed write as [`Error::Stdout`](crate::Error::Stdout).
#[macro_export]
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::console::write(format_args!($($arg)*))
    };
}

/// `eprintln!` that never panics: a failed write to stderr is dropped.
#[macro_export]
macro_rules! errln {
    ($($arg:tt)*) => {
        $crate::console::note(format_args!("{}\n", format_args!($($arg)*)))
    };
}
