//! `ffvk results`: merging the results files of a suite's shards, and their report.

use std::path::PathBuf;
use std::process::ExitCode;

use ffvk_cli::regress;

use super::render::{finish_results, Outputs};

#[derive(clap::Subcommand, Debug, Clone)]
pub(crate) enum ResultsAction {
    /// Join the results files of every shard of one suite (each written by `render
    /// --partition K/N --json FILE`) into one summary, and optionally one JSON and one JUnit
    /// file; refuses shards of different suites, a shard given twice and missing shards.
    /// Exits as `render --check` does: 0 pass, 1 a difference or missing reference, 2 an error.
    Merge {
        /// The shards' results files.
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// Write the merged results as JSON.
        #[arg(long, value_name = "FILE")]
        json: Option<PathBuf>,
        /// Write the merged results as JUnit XML.
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
        /// Write the merged results as an HTML report into DIR.
        #[arg(long, value_name = "DIR")]
        report: Option<PathBuf>,
    },
    /// Write the HTML report of results files (one run's, or every shard's: they are merged
    /// first) into DIR. The image paths the files record are read as they were written
    /// (relative ones from the current folder). Exits as `render --check` does.
    Report {
        /// The results files (`render --json`).
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// The folder to write index.html, report.css and images/ into.
        #[arg(short, long, value_name = "DIR", required = true)]
        out: PathBuf,
    },
}

/// Merges or reports what `action` names.
pub(crate) fn run(action: &ResultsAction) -> ffvk_cli::Result<ExitCode> {
    let (files, outputs) = match action {
        ResultsAction::Merge {
            files,
            json,
            junit,
            report,
        } => (
            files,
            Outputs {
                json: json.as_deref(),
                junit: junit.as_deref(),
                report: report.as_deref(),
            },
        ),
        ResultsAction::Report { files, out } => (
            files,
            Outputs {
                report: Some(out),
                ..Outputs::default()
            },
        ),
    };
    let parts = files
        .iter()
        .map(|f| Ok((f.clone(), regress::results::Results::read_json(f)?)))
        .collect::<ffvk_cli::Result<Vec<_>>>()?;
    // The merged files' own rule: not over an input, each other, or the references the
    // runs checked against.
    let written: Vec<(&'static str, &std::path::Path)> = [
        ("--junit", outputs.junit),
        ("--json", outputs.json),
        ("--report", outputs.report),
    ]
    .into_iter()
    .filter_map(|(flag, path)| path.map(|p| (flag, p)))
    .collect();
    let inputs: Vec<&std::path::Path> = files.iter().map(PathBuf::as_path).collect();
    // What the runs read and wrote (scene files, images, references, maps) is this command's
    // input too: no results file or report may replace one, by any spelling.
    for (_, results) in &parts {
        for row in results.runs.iter().flat_map(|run| &run.rows) {
            let named = [
                &row.output,
                &row.diff,
                &row.channels,
                &row.replaced,
                &row.reference,
            ];
            for path in named.into_iter().flatten() {
                ffvk::files::note_input(path);
            }
        }
        // Each scene once, with what it reads (textures, glTF files, buffers, images).
        let mut scenes: Vec<&std::path::Path> = results
            .runs
            .iter()
            .flat_map(|run| &run.rows)
            .map(|r| r.file.as_path())
            .collect();
        scenes.sort();
        scenes.dedup();
        for scene in scenes {
            for input in ffvk::scene::inputs(scene, &ffvk::scene::Limits::default()) {
                ffvk::files::note_input(&input);
            }
        }
    }
    let references: Vec<PathBuf> = parts
        .iter()
        .flat_map(|(_, r)| r.runs.iter().filter_map(|run| run.info.references.clone()))
        .collect();
    let references: Vec<&std::path::Path> = references.iter().map(PathBuf::as_path).collect();
    regress::refuse_overlaps(&written, &inputs, &[], &references)?;
    for (_, path) in &written {
        if let Some(input) = ffvk::files::input_named(path) {
            return Err(ffvk_cli::Error::OverwritesInput {
                path: path.to_path_buf(),
                input,
            });
        }
    }
    super::render::expect_results_names(outputs.json, outputs.junit)?;
    let merged = regress::results::Results::merge(parts)?;
    let checked = merged.runs.iter().any(|r| r.info.references.is_some());
    if let Some(dir) = outputs.report {
        let references: Vec<&std::path::Path> = merged
            .runs
            .iter()
            .filter_map(|r| r.info.references.as_deref())
            .collect();
        regress::report::claim(dir, &references)?;
    }
    finish_results(&merged, checked, &outputs)
}
