//! Running `povray` and `lancer` as child processes with a time limit, so one scene that hangs
//! or crashes cannot take the whole conformance run down with it.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// How a child process ended.
#[derive(Debug)]
pub struct Outcome {
    /// Exit code; `None` when killed by a signal or by our time limit.
    pub code: Option<i32>,
    pub timed_out: bool,
    pub seconds: f64,
    pub stderr: String,
}

/// Runs `program args` in `dir` with stdin closed, collecting stderr, and kills it after `limit`.
/// Stdout is discarded: both renderers report on stderr.
pub fn run(
    program: &Path,
    args: &[String],
    dir: &Path,
    limit: Duration,
) -> Result<Outcome, String> {
    let start = Instant::now();
    let mut child = Command::new(program)
        .args(args)
        .current_dir(dir)
        // lancer reads no povray.ini or povray.conf: the report must not depend on the machine.
        .env(crate::config::NO_CONFIG_ENV, "1")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot run {}: {e}", program.display()))?;
    // Reading on another thread keeps a chatty child from blocking on a full pipe while we wait.
    let mut pipe = child.stderr.take().expect("stderr was piped");
    let reader = std::thread::spawn(move || {
        let mut buf = Vec::new();
        let _ = pipe.read_to_end(&mut buf);
        buf
    });
    let mut timed_out = false;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if start.elapsed() >= limit => {
                timed_out = true;
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(10)),
            Err(e) => return Err(format!("waiting for {}: {e}", program.display())),
        }
    };
    let seconds = start.elapsed().as_secs_f64();
    let bytes = reader.join().unwrap_or_default();
    Ok(Outcome {
        code: status.and_then(|s| s.code()),
        timed_out,
        seconds,
        stderr: String::from_utf8_lossy(&bytes).into_owned(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_limit_kills_the_child() {
        let sh = Path::new("/bin/sh");
        if !sh.exists() {
            return;
        }
        let o = run(
            sh,
            &["-c".into(), "echo hi >&2; sleep 5".into()],
            Path::new("."),
            Duration::from_millis(200),
        )
        .unwrap();
        assert!(o.timed_out);
        assert!(o.seconds < 4.0);
        assert!(o.stderr.contains("hi"));
    }

    #[test]
    fn exit_code_is_reported() {
        let sh = Path::new("/bin/sh");
        if !sh.exists() {
            return;
        }
        let o = run(
            sh,
            &["-c".into(), "exit 3".into()],
            Path::new("."),
            Duration::from_secs(5),
        )
        .unwrap();
        assert_eq!(o.code, Some(3));
        assert!(!o.timed_out);
    }
}
