//! `ffvk compare`: two images, per-channel differences, the share over a threshold, FLIP.

use std::path::PathBuf;
use std::process::ExitCode;

use ffvk::images::compare;
use ffvk::images::save_png;

use super::common::ToleranceArgs;

/// `ffvk compare`'s options.
#[derive(clap::Args, Debug, Clone)]
pub(crate) struct CompareArgs {
    pub(crate) expected: PathBuf,
    pub(crate) actual: PathBuf,
    /// Write a heat map of the differences (FLIP, magma) here.
    #[arg(long)]
    pub(crate) diff: Option<PathBuf>,
    #[command(flatten)]
    pub(crate) tolerance: ToleranceArgs,
}

/// Compares the two images; exit 1 when they differ past the tolerance.
pub(crate) fn run(args: &CompareArgs) -> ffvk_cli::Result<ExitCode> {
    let CompareArgs {
        expected,
        actual,
        diff,
        tolerance,
    } = args;
    let tolerance = tolerance.tolerance();
    tolerance.validate()?;
    ffvk::files::note_input(expected);
    ffvk::files::note_input(actual);
    if let Some(path) = diff {
        super::common::expect_extension(path, "png", "--diff writes a PNG heat map: expected a .png path")?;
        // By identity, before anything is compared: `x/../a.png` names `a.png`.
        if let Some(input) = ffvk::files::input_named(path) {
            return Err(ffvk_cli::Error::OverwritesInput {
                path: path.clone(),
                input,
            });
        }
    }
    let e = compare::load_image(expected)?;
    let a = compare::load_image(actual)?;
    let c = compare::compare(&e, &a, &tolerance).map_err(|source| ffvk_cli::Error::Compare {
        expected: expected.clone(),
        actual: actual.clone(),
        source,
    })?;
    ffvk_cli::outln!("{}", c.summary())?;
    if let Some(path) = diff {
        save_png(&compare::heat_map(&e, &a, tolerance.threshold)?, path)?;
        ffvk_cli::outln!("diff heat map: {}", path.display())?;
    }
    if c.passes(&tolerance) {
        ffvk_cli::outln!(
            "PASS (threshold {}/255, max share {}, max FLIP {})",
            tolerance.threshold,
            tolerance.max_share,
            tolerance.max_flip
        )?;
        Ok(ExitCode::SUCCESS)
    } else {
        ffvk_cli::outln!(
            "FAIL (threshold {}/255, max share {}, max FLIP {})",
            tolerance.threshold,
            tolerance.max_share,
            tolerance.max_flip
        )?;
        Ok(ExitCode::FAILURE)
    }
}
