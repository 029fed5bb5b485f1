//! Regression runs over worker processes (`ffvk render --jobs N`).
//!
//! Each worker is the `ffvk` program itself, started with the run's own arguments and
//! `--worker`: it opens one renderer, then renders the scenes the parent sends it, one at a
//! time, and answers each with its rows. Processes rather than threads because lavapipe runs
//! the vertex stage on the submitting thread and one device per process is what every driver
//! supports well, and so that a crash (a driver fault, an abort, an out-of-memory kill) costs
//! the one scene that was rendering: that scene becomes an error row naming the signal or exit
//! status and the worker's last lines on stderr, a fresh worker takes the next scene, and the
//! others go on. A scene that takes longer than the timeout has its worker killed the same way.
//!
//! The protocol is JSON lines: the parent writes one [`SceneFile`] per line on the worker's
//! stdin; the worker writes lines starting with [`PREFIX`] on its stdout: first
//! [`Reply::Ready`] (or [`Reply::Failed`] when it has no renderer), then per scene its
//! [`Reply::Note`]s and its [`Reply::Rows`]. Any other stdout line (a driver's chatter) and every
//! stderr line are passed on as [`Message::Output`]. Rows come back in suite order whatever the
//! number of workers, and so do the notes.

use std::collections::{BTreeMap, VecDeque};
use std::ffi::OsString;
use std::io::{self, BufRead, BufReader, Write};
use std::path::PathBuf;
use std::process::{Child, ChildStdin, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};

use super::results::DeviceSummary;
use super::{render_file, Job, Message, Row, SceneFile};
use ffvk::{Renderer, RendererOptions};

/// What starts a worker: a program and its arguments (the binary passes itself, its own
/// arguments and `--worker`).
#[derive(Debug, Clone)]
pub struct WorkerCommand {
    /// The program.
    pub program: PathBuf,
    /// Its arguments.
    pub args: Vec<OsString>,
}

/// How many workers, with which lavapipe threads, and how long a scene may take.
#[derive(Debug, Clone)]
pub struct PoolOptions {
    /// Worker processes (at least 1; never more than there are scenes).
    pub jobs: usize,
    /// LP_NUM_THREADS for each worker, when set.
    pub lp_num_threads: Option<String>,
    /// How long one scene (all its modes) or a worker's start may take before the worker is
    /// killed and the scene reported as an error.
    pub timeout: Duration,
}

/// The start of every protocol line on a worker's stdout.
pub const PREFIX: &str = "@ffvk-worker ";

/// The environment variable that makes a worker fail on purpose, for the tests of crash and
/// timeout handling: `abort:NAME` aborts (SIGABRT) when asked for scene NAME, `hang:NAME`
/// sleeps forever instead.
pub const FAULT_VAR: &str = "FFVK_WORKER_FAULT";

/// A deliberate fault ([`FAULT_VAR`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Fault {
    /// Abort the process when asked for this scene.
    Abort(String),
    /// Never answer for this scene.
    Hang(String),
}

impl Fault {
    /// The fault [`FAULT_VAR`] asks for, if any.
    pub fn from_env() -> Option<Fault> {
        let value = std::env::var(FAULT_VAR).ok()?;
        match value.split_once(':')? {
            ("abort", name) => Some(Fault::Abort(name.to_owned())),
            ("hang", name) => Some(Fault::Hang(name.to_owned())),
            _ => None,
        }
    }
}

/// What a worker writes.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Reply {
    /// The worker has its renderer, on this device.
    Ready(DeviceSummary),
    /// The worker could not make a renderer (no device, no driver): the run cannot go on.
    Failed(String),
    /// Something the scene being rendered reported.
    Note(Note),
    /// The scene's rows: it is done.
    Rows(Vec<Row>),
}

/// A [`Message`] that crossed from a worker.
#[allow(missing_docs)] // each variant's text names its fields
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Note {
    /// [`Message::Warning`].
    Warning { text: String, times: usize },
    /// [`Message::Chose`].
    Chose { scene: PathBuf, text: String },
    /// [`Message::Wrote`].
    Wrote { scene: PathBuf, image: PathBuf },
}

impl Note {
    fn of(m: Message) -> Option<Note> {
        Some(match m {
            Message::Warning { text, times } => Note::Warning {
                text: text.into(),
                times,
            },
            Message::Chose { scene, text } => Note::Chose {
                scene: scene.into(),
                text: text.into(),
            },
            Message::Wrote { scene, image } => Note::Wrote {
                scene: scene.into(),
                image: image.into(),
            },
            Message::Output { .. } => return None,
        })
    }

    fn message(&self) -> Message<'_> {
        match self {
            Note::Warning { text, times } => Message::Warning { text, times: *times },
            Note::Chose { scene, text } => Message::Chose { scene, text },
            Note::Wrote { scene, image } => Message::Wrote { scene, image },
        }
    }
}

/// Worker processes that could not start or be talked to: the run cannot go on.
#[allow(missing_docs)] // each variant's text names its fields
#[derive(Debug, thiserror::Error)]
pub enum WorkerError {
    /// The program could not be started.
    #[error("cannot start the worker process {}: {source}", .program.display())]
    Spawn { program: PathBuf, source: io::Error },
    /// A worker ended or failed before it was ready to render.
    #[error("a worker process could not start rendering: {message}")]
    Startup { message: String },
}

/// A worker's side: makes a renderer and renders the scenes read from stdin, answering on
/// stdout, until stdin ends. Without a renderer, says why ([`Reply::Failed`]) and returns
/// the error.
pub fn worker_main(options: &RendererOptions, mut job: Job) -> crate::Result<()> {
    let mut stdout = io::stdout().lock();
    // Every state its specialized pipeline, however many came before: under the default
    // policy a worker past its budget of states would draw later scenes with the uber-shader,
    // and which scenes come later depends on the number of workers.
    let mut options = options.clone();
    options.specialize = ffvk::Specialize::Always;
    let mut renderer = match Renderer::new(&options) {
        Ok(r) => r,
        Err(e) => {
            let _ = reply(&mut stdout, &Reply::Failed(e.to_string()));
            return Err(e.into());
        }
    };
    job.driver_family = Some(super::driver_family(renderer.device_info()));
    serve(
        &mut renderer,
        &job,
        io::stdin().lock(),
        &mut stdout,
        Fault::from_env().as_ref(),
    )
    .map_err(|source| crate::Error::Write {
        path: "standard output".into(),
        source,
    })
}

/// Renders the scenes read from `input` (one JSON [`SceneFile`] per line) and answers on
/// `output`, first with [`Reply::Ready`].
pub fn serve(
    renderer: &mut Renderer,
    job: &Job,
    input: impl BufRead,
    output: &mut impl Write,
    fault: Option<&Fault>,
) -> io::Result<()> {
    reply(output, &Reply::Ready(DeviceSummary::of(renderer.device_info())))?;
    for line in input.lines() {
        let line = line?;
        if line.trim().is_empty() {
            continue;
        }
        let file: SceneFile = serde_json::from_str(&line).map_err(io::Error::other)?;
        match fault {
            Some(Fault::Abort(name)) if *name == file.name => std::process::abort(),
            Some(Fault::Hang(name)) if *name == file.name => loop {
                std::thread::sleep(Duration::from_secs(3600));
            },
            _ => {}
        }
        let mut notes = Vec::new();
        let rows = render_file(renderer, job, &file, &mut |m| notes.extend(Note::of(m)));
        for note in notes {
            reply(output, &Reply::Note(note))?;
        }
        reply(output, &Reply::Rows(rows))?;
    }
    Ok(())
}

fn reply(output: &mut impl Write, reply: &Reply) -> io::Result<()> {
    let json = serde_json::to_string(reply).map_err(io::Error::other)?;
    writeln!(output, "{PREFIX}{json}")?;
    output.flush()
}

/// Renders `files` (one shard of `job`'s suite) over worker processes; rows and notes reach
/// `log` and the result in `files`' order. Returns the rows and the device the first worker
/// reported. Fails only when a worker cannot start (no program, no device).
pub fn run_pool(
    job: &Job,
    files: &[SceneFile],
    worker: &WorkerCommand,
    options: &PoolOptions,
    log: &mut dyn FnMut(Message),
) -> Result<(Vec<Row>, Option<DeviceSummary>), WorkerError> {
    let jobs = options.jobs.clamp(1, files.len().max(1));
    let next = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    let (tx, rx) = mpsc::channel::<Event>();
    std::thread::scope(|s| {
        for _ in 0..jobs {
            let tx = tx.clone();
            let (next, stop) = (&next, &stop);
            s.spawn(move || slot(job, files, worker, options, next, stop, tx));
        }
        drop(tx);
        let mut device = None;
        let mut fatal = None;
        let mut done: BTreeMap<usize, (Vec<Note>, Vec<Row>)> = BTreeMap::new();
        let mut rows = Vec::new();
        // Every sender is gone once every slot has stopped its worker.
        for event in rx {
            match event {
                Event::Ready(d) => {
                    device.get_or_insert(d);
                }
                Event::Output(text) => log(Message::Output { text: &text }),
                Event::Fatal(e) => {
                    fatal.get_or_insert(e);
                }
                Event::Done {
                    position,
                    notes,
                    rows: r,
                } => {
                    done.insert(position, (notes, r));
                    // Pass on the longest finished prefix, in order.
                    while let Some((notes, r)) = done.remove(&rows.len()) {
                        for n in &notes {
                            log(n.message());
                        }
                        rows.push(r);
                    }
                }
            }
        }
        match fatal {
            Some(e) => Err(e),
            None => Ok((rows.into_iter().flatten().collect(), device)),
        }
    })
}

/// What a slot tells the coordinating thread.
enum Event {
    Ready(DeviceSummary),
    Output(String),
    Fatal(WorkerError),
    Done {
        position: usize,
        notes: Vec<Note>,
        rows: Vec<Row>,
    },
}

/// One worker's slot: takes the next scene, renders it in its worker (starting one when it
/// has none), replaces a worker that was lost, until the scenes run out.
fn slot(
    job: &Job,
    files: &[SceneFile],
    command: &WorkerCommand,
    options: &PoolOptions,
    next: &AtomicUsize,
    stop: &AtomicBool,
    tx: mpsc::Sender<Event>,
) {
    let mut worker: Option<Worker> = None;
    while !stop.load(Ordering::Relaxed) {
        let position = next.fetch_add(1, Ordering::Relaxed);
        let Some(file) = files.get(position) else {
            break;
        };
        let mut w = match worker.take() {
            Some(w) => w,
            None => match Worker::start(command, options, &tx) {
                Ok((w, device)) => {
                    let _ = tx.send(Event::Ready(device));
                    w
                }
                Err(e) => {
                    stop.store(true, Ordering::Relaxed);
                    let _ = tx.send(Event::Fatal(e));
                    break;
                }
            },
        };
        let started = Instant::now();
        let event = match w.render(file) {
            Ok((notes, rows)) => {
                worker = Some(w);
                Event::Done {
                    position,
                    notes,
                    rows,
                }
            }
            Err(lost) => {
                let message = w.lose(lost);
                let seconds = started.elapsed().as_secs_f64();
                Event::Done {
                    position,
                    notes: Vec::new(),
                    rows: Row::errors(job, file, &message, seconds),
                }
            }
        };
        let _ = tx.send(event);
    }
    if let Some(w) = worker {
        if let Some(text) = w.finish() {
            let _ = tx.send(Event::Output(text));
        }
    }
}

/// Why a worker stopped answering.
enum Lost {
    /// Its stdout ended: it exited or was killed.
    Ended,
    /// No rows within the timeout.
    Timeout,
    /// It wrote something that is not a reply where one was due.
    Garbled(String),
}

/// What a wait for a worker's next reply gave.
enum Wait {
    Reply(Reply),
    Lost(Lost),
}

/// How many of a worker's last stderr lines an error row quotes.
const STDERR_TAIL: usize = 12;

/// A running worker process.
struct Worker {
    child: Child,
    stdin: Option<ChildStdin>,
    /// Protocol lines from the stdout reader thread; disconnected at end of stdout.
    replies: mpsc::Receiver<String>,
    /// The last lines of stderr.
    tail: Arc<Mutex<VecDeque<String>>>,
    /// How long a scene may take (for the message when one took longer).
    timeout: Duration,
    readers: Vec<JoinHandle<()>>,
}

impl Worker {
    /// Starts a worker and waits for it to be ready.
    fn start(
        command: &WorkerCommand,
        options: &PoolOptions,
        tx: &mpsc::Sender<Event>,
    ) -> Result<(Worker, DeviceSummary), WorkerError> {
        let mut c = Command::new(&command.program);
        c.args(&command.args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        if let Some(threads) = &options.lp_num_threads {
            c.env("LP_NUM_THREADS", threads);
        }
        let mut child = c.spawn().map_err(|source| WorkerError::Spawn {
            program: command.program.clone(),
            source,
        })?;
        let stdin = child.stdin.take();
        let (stdout, stderr) = (child.stdout.take(), child.stderr.take());
        let (reply_tx, replies) = mpsc::channel();
        let tail = Arc::new(Mutex::new(VecDeque::new()));
        let mut readers = Vec::new();
        if let Some(out) = stdout {
            let output = tx.clone();
            readers.push(std::thread::spawn(move || {
                for line in BufReader::new(out).lines().map_while(|l| l.ok()) {
                    match line.strip_prefix(PREFIX) {
                        Some(json) => {
                            if reply_tx.send(json.to_owned()).is_err() {
                                break;
                            }
                        }
                        None => {
                            let _ = output.send(Event::Output(line));
                        }
                    }
                }
            }));
        }
        if let Some(err) = stderr {
            let (output, tail) = (tx.clone(), Arc::clone(&tail));
            readers.push(std::thread::spawn(move || {
                for line in BufReader::new(err).lines().map_while(|l| l.ok()) {
                    if let Ok(mut t) = tail.lock() {
                        if t.len() == STDERR_TAIL {
                            t.pop_front();
                        }
                        t.push_back(line.clone());
                    }
                    let _ = output.send(Event::Output(line));
                }
            }));
        }
        let worker = Worker {
            child,
            stdin,
            replies,
            tail,
            readers,
            timeout: options.timeout,
        };
        match worker.next(Instant::now() + options.timeout) {
            Wait::Reply(Reply::Ready(device)) => Ok((worker, device)),
            Wait::Reply(Reply::Failed(message)) => {
                worker.lose(Lost::Ended);
                Err(WorkerError::Startup { message })
            }
            Wait::Reply(other) => Err(WorkerError::Startup {
                message: worker.lose(Lost::Garbled(format!("{other:?}"))),
            }),
            Wait::Lost(lost) => Err(WorkerError::Startup {
                message: worker.lose(lost),
            }),
        }
    }

    /// The next reply, or why none will come.
    fn next(&self, deadline: Instant) -> Wait {
        let left = deadline.saturating_duration_since(Instant::now());
        match self.replies.recv_timeout(left) {
            Ok(json) => match serde_json::from_str(&json) {
                Ok(reply) => Wait::Reply(reply),
                Err(_) => Wait::Lost(Lost::Garbled(json)),
            },
            Err(mpsc::RecvTimeoutError::Timeout) => Wait::Lost(Lost::Timeout),
            Err(mpsc::RecvTimeoutError::Disconnected) => Wait::Lost(Lost::Ended),
        }
    }

    /// Sends `file` and collects its notes and rows.
    fn render(&mut self, file: &SceneFile) -> Result<(Vec<Note>, Vec<Row>), Lost> {
        let request = serde_json::to_string(file).map_err(|e| Lost::Garbled(e.to_string()))?;
        let stdin = self.stdin.as_mut().ok_or(Lost::Ended)?;
        if writeln!(stdin, "{request}").and_then(|()| stdin.flush()).is_err() {
            return Err(Lost::Ended);
        }
        let deadline = Instant::now() + self.timeout;
        let mut notes = Vec::new();
        loop {
            match self.next(deadline) {
                Wait::Reply(Reply::Note(n)) => notes.push(n),
                Wait::Reply(Reply::Rows(rows)) => return Ok((notes, rows)),
                Wait::Reply(other) => return Err(Lost::Garbled(format!("{other:?}"))),
                Wait::Lost(lost) => return Err(lost),
            }
        }
    }

    /// Kills the worker (if it still runs), reaps it and says what happened, with its last
    /// lines on stderr.
    fn lose(mut self, lost: Lost) -> String {
        // Killing a process that already exited (a zombie until reaped) does nothing, so the
        // status is the one it died with.
        let _ = self.child.kill();
        let status = self.child.wait();
        self.stdin = None;
        for reader in self.readers.drain(..) {
            let _ = reader.join();
        }
        let what = match (&lost, &status) {
            (Lost::Timeout, _) => format!(
                "no result within the timeout of {} s: its worker process was killed",
                self.timeout.as_secs_f64()
            ),
            (Lost::Garbled(text), _) => format!(
                "its worker process answered out of protocol ({}) and was stopped",
                shorten(text)
            ),
            (Lost::Ended, Ok(status)) => format!("its worker process {}", describe(status)),
            (Lost::Ended, Err(e)) => format!("its worker process ended and could not be reaped: {e}"),
        };
        let tail: Vec<String> = self
            .tail
            .lock()
            .map(|t| t.iter().cloned().collect())
            .unwrap_or_default();
        if tail.is_empty() {
            what
        } else {
            format!("{what}; its last lines on stderr:\n{}", tail.join("\n"))
        }
    }

    /// Closes the worker's stdin (it exits when its input ends) and reaps it; says so when it
    /// did not exit cleanly.
    fn finish(mut self) -> Option<String> {
        self.stdin = None;
        let status = self.child.wait();
        for reader in self.readers.drain(..) {
            let _ = reader.join();
        }
        match status {
            Ok(s) if s.success() => None,
            Ok(s) => Some(format!("a worker process {} after its last scene", describe(&s))),
            Err(e) => Some(format!("a worker process could not be reaped: {e}")),
        }
    }
}

/// `exited with status N` or `was killed by signal N (SIGNAME)`.
fn describe(status: &ExitStatus) -> String {
    use std::os::unix::process::ExitStatusExt;
    match (status.code(), status.signal()) {
        (Some(code), _) => format!("exited with status {code}"),
        (None, Some(signal)) => {
            let name = match signal {
                4 => " (SIGILL)",
                6 => " (SIGABRT)",
                7 => " (SIGBUS)",
                8 => " (SIGFPE)",
                9 => " (SIGKILL)",
                11 => " (SIGSEGV)",
                15 => " (SIGTERM)",
                _ => "",
            };
            format!("was killed by signal {signal}{name}")
        }
        (None, None) => "ended".into(),
    }
}

/// At most 200 characters of `text`.
fn shorten(text: &str) -> String {
    match text.char_indices().nth(200) {
        Some((i, _)) => format!("{}…", &text[..i]),
        None => text.to_owned(),
    }
}

/// The default number of workers: the CPUs this process may use.
pub fn default_jobs() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// LP_NUM_THREADS for each of `jobs` workers when the environment does not set it: the CPUs
/// shared out among the workers, at least one each.
pub fn default_lp_threads(jobs: usize) -> usize {
    (default_jobs() / jobs.max(1)).max(1)
}

/// How [`run_suite`] runs its workers.
#[derive(Debug, Clone)]
pub struct SuiteOptions {
    /// Worker processes; `None`: [`default_jobs`]. Never more than there are scenes.
    pub jobs: Option<usize>,
    /// LP_NUM_THREADS for each worker; `None`: the environment's, else
    /// [`default_lp_threads`].
    pub lp_num_threads: Option<String>,
    /// How long one scene may take ([`PoolOptions::timeout`]).
    pub timeout: Duration,
}

/// Renders `job`'s suite (its partition, when it has one) over worker processes and returns
/// the results with what the run was. Fails before rendering for the reasons
/// [`super::job_files`] gives, or when a worker cannot start.
pub fn run_suite(
    job: &Job,
    worker: &WorkerCommand,
    options: &SuiteOptions,
    log: &mut dyn FnMut(Message),
) -> crate::Result<super::results::Results> {
    let started = std::time::SystemTime::now();
    let clock = Instant::now();
    let (files, suite) = super::job_files(job)?;
    let jobs = options
        .jobs
        .unwrap_or_else(default_jobs)
        .clamp(1, files.len().max(1));
    let lp_num_threads = match (&options.lp_num_threads, std::env::var("LP_NUM_THREADS")) {
        (Some(t), _) => t.clone(),
        (None, Ok(v)) if !v.trim().is_empty() => v,
        _ => default_lp_threads(jobs).to_string(),
    };
    let pool = PoolOptions {
        jobs,
        lp_num_threads: Some(lp_num_threads.clone()),
        timeout: options.timeout,
    };
    let (rows, device) = run_pool(job, &files, worker, &pool, log)?;
    let info = super::results::RunInfo {
        ffvk: env!("CARGO_PKG_VERSION").into(),
        device,
        jobs,
        lp_num_threads: Some(lp_num_threads),
        partition: job.partition,
        suite_scenes: suite,
        scenes: files.len(),
        modes: job.modes.iter().map(|m| m.name().to_owned()).collect(),
        references: job.references.clone(),
        bless: job.bless,
        tolerance: job.tolerance,
        timestamp: super::results::utc_timestamp(started),
        hostname: super::results::hostname(),
        seconds: clock.elapsed().as_secs_f64(),
    };
    Ok(super::results::Results::single(info, rows))
}
