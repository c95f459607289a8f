//! Reading the renderers' messages (first error, panic, missing keywords, POV-Ray's own times)
//! and writing the conformance report: a Markdown page for people and a TSV for scripts.

use std::collections::{BTreeMap, HashMap};
use std::fmt::Write as _;

use super::{Class, SceneResult};

/// Keywords lancer warned about ("'kw' is not supported by lancer yet", "#switch is not
/// supported", "the function f is not supported"), each once, in first-seen order.
pub fn missing_keywords(stderr: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for line in stderr.lines() {
        // Features random in POV-Ray itself, which no renderer can match pixel for pixel.
        if let Some(at) = line.find(" is random in POV-Ray") {
            let head = line[..at].trim_end().trim_end_matches('\'');
            if let Some(q) = head.rfind('\'') {
                let kw = format!("{} (random in POV-Ray)", &head[q + 1..]);
                if !out.contains(&kw) {
                    out.push(kw);
                }
            }
            continue;
        }
        let Some(at) = line.find(" is not supported") else {
            continue;
        };
        let head = line[..at].trim_end();
        // lancer quotes what it does not support, keyword first ('normal (surface
        // perturbation)'); errors name it bare (#switch, the function vstr).
        let quoted = head
            .strip_suffix('\'')
            .and_then(|h| h.rfind(" '").map(|i| &h[i + 2..]));
        let word = match quoted {
            Some(q) => q.split_whitespace().next(),
            None => head.split_whitespace().last(),
        };
        let Some(word) = word else {
            continue;
        };
        let kw = word.trim_matches(|c| c == '\'' || c == '"' || c == '`');
        if !kw.is_empty() && !out.iter().any(|k| k == kw) {
            out.push(kw.to_string());
        }
    }
    out
}

/// lancer's first error: the diagnostic's message plus the `file:line:col` codespan prints
/// under it, shortened to the file name.
pub fn first_error(stderr: &str) -> String {
    let lines: Vec<&str> = stderr.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        let msg = if let Some(m) = line.strip_prefix("error: ") {
            m
        } else if let Some(m) = line.strip_prefix("lancer: ") {
            m
        } else {
            continue;
        };
        let place = lines[i + 1..]
            .iter()
            .take(2)
            .find_map(|l| l.split("┌─ ").nth(1))
            .map(|p| {
                let p = p.trim();
                p.rsplit('/').next().unwrap_or(p).to_string()
            });
        return match place {
            Some(p) => format!("{msg} ({p})"),
            None => msg.to_string(),
        };
    }
    lines
        .iter()
        .rev()
        .find(|l| !l.trim().is_empty())
        .map_or_else(|| "no message".to_string(), |l| l.trim().to_string())
}

/// Where and why lancer panicked (Rust prints `thread '…' panicked at file:line:col:` then the
/// message), or the signal that killed it.
pub fn panic_message(stderr: &str, code: Option<i32>) -> String {
    let lines: Vec<&str> = stderr.lines().collect();
    if let Some(i) = lines.iter().position(|l| l.contains("panicked at")) {
        let at = lines[i].split("panicked at").nth(1).unwrap_or("").trim();
        let msg = lines.get(i + 1).map_or("", |l| l.trim());
        return format!("{msg} (at {})", at.trim_end_matches(':'));
    }
    match code {
        None => "killed by a signal".to_string(),
        Some(c) => format!("exit code {c}"),
    }
}

/// POV-Ray's first error: the line naming the file and the error, joined with the indented
/// lines POV-Ray wraps it onto.
pub fn pov_error(stderr: &str) -> String {
    let lines: Vec<&str> = stderr.lines().collect();
    // "Possible Parse Error" is POV-Ray's name for a warning.
    let is_error =
        |l: &&str| (l.contains("Error") || l.contains("error")) && !l.contains("Possible");
    let Some(i) = lines.iter().position(is_error) else {
        return "POV-Ray failed without an error message".to_string();
    };
    let mut msg = lines[i].trim().to_string();
    for l in &lines[i + 1..] {
        if l.starts_with(' ') && !l.trim().is_empty() {
            msg.push(' ');
            msg.push_str(l.trim());
        } else {
            break;
        }
    }
    msg
}

/// The sum of the times POV-Ray reports for its phases ("Parse Time: … (0.123 seconds)" and
/// so on): its own work, without the start-up the wall clock also counts.
pub fn pov_work_seconds(stderr: &str) -> f64 {
    stderr
        .lines()
        .filter(|l| l.contains(" Time:"))
        .filter_map(|l| {
            let open = l.rfind('(')?;
            let rest = &l[open + 1..];
            rest.strip_suffix(" seconds)")?.trim().parse::<f64>().ok()
        })
        .sum()
}

pub fn progress_line(r: &SceneResult) -> String {
    let ssim = r.ssim.map_or(String::new(), |s| format!(" {s:.3}"));
    format!(
        "{}: {}{} (lancer {:.2} s, povray {:.2} s)",
        r.name,
        r.class.label(),
        ssim,
        r.lancer_seconds,
        r.pov.seconds
    )
}

/// Counts per class, in the order the report lists them.
pub struct Summary {
    pub total: usize,
    pub pov_failed: usize,
    pub good: usize,
    pub close: usize,
    pub low: usize,
    pub error: usize,
    pub panic: usize,
    pub timeout: usize,
}

pub fn summarize(results: &[SceneResult]) -> Summary {
    let mut s = Summary {
        total: results.len(),
        pov_failed: 0,
        good: 0,
        close: 0,
        low: 0,
        error: 0,
        panic: 0,
        timeout: 0,
    };
    for r in results {
        match r.class {
            Class::Good => s.good += 1,
            Class::Close => s.close += 1,
            Class::Low => s.low += 1,
            Class::Error(_) => s.error += 1,
            Class::Panic(_) => s.panic += 1,
            Class::Timeout => s.timeout += 1,
            Class::PovFailed(_) => s.pov_failed += 1,
        }
    }
    s
}

impl Summary {
    pub fn counted(&self) -> usize {
        self.total - self.pov_failed
    }

    pub fn line(&self) -> String {
        format!(
            "{} scenes, {} that POV-Ray renders: {} at SSIM ≥ 0.95, {} at ≥ 0.80, {} lower, {} lancer errors, {} panics, {} timeouts ({} POV-Ray failures not counted)",
            self.total,
            self.counted(),
            self.good,
            self.close,
            self.low,
            self.error,
            self.panic,
            self.timeout,
            self.pov_failed
        )
    }
}

/// Missing keywords ranked by how many scenes they appear in that do not reach SSIM 0.95, and
/// in how many of those they are the only missing keyword (implementing it alone could fix
/// the scene).
pub fn ranked_missing(results: &[SceneResult]) -> Vec<(String, usize, usize)> {
    let mut count: HashMap<&str, (usize, usize)> = HashMap::new();
    for r in results {
        if matches!(r.class, Class::Good | Class::PovFailed(_)) {
            continue;
        }
        for k in &r.missing {
            let e = count.entry(k.as_str()).or_default();
            e.0 += 1;
            if r.missing.len() == 1 {
                e.1 += 1;
            }
        }
    }
    let mut v: Vec<(String, usize, usize)> = count
        .into_iter()
        .map(|(k, (n, only))| (k.to_string(), n, only))
        .collect();
    v.sort_by(|a, b| b.1.cmp(&a.1).then(b.2.cmp(&a.2)).then(a.0.cmp(&b.0)));
    v
}

/// lancer's error messages grouped (numbers and places stripped), most frequent first.
fn ranked_errors(results: &[SceneResult]) -> Vec<(String, usize)> {
    let mut count: BTreeMap<String, usize> = BTreeMap::new();
    for r in results {
        if let Class::Error(m) | Class::Panic(m) = &r.class {
            let key = m.split(" (").next().unwrap_or(m).to_string();
            *count.entry(key).or_default() += 1;
        }
    }
    let mut v: Vec<(String, usize)> = count.into_iter().collect();
    v.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    v
}

/// Scenes whose difference from POV-Ray has a measured reason that is not a missing keyword
/// (docs/known-differences.tsv: `scene<TAB>reason`, `#` comments), by scene name.
pub type Known = BTreeMap<String, String>;

pub fn read_known(path: &std::path::Path) -> Result<Known, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    parse_known(&text).map_err(|(line, why)| format!("{}:{line}: {why}", path.display()))
}

fn parse_known(text: &str) -> Result<Known, (usize, String)> {
    let mut known = Known::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim_end();
        if line.is_empty() || line.starts_with('#') || (i == 0 && line.starts_with("scene\t")) {
            continue;
        }
        let Some((scene, reason)) = line.split_once('\t') else {
            return Err((i + 1, "expected `scene<TAB>reason`".into()));
        };
        if reason.trim().is_empty() {
            return Err((i + 1, format!("{scene} has no reason")));
        }
        known.insert(scene.trim().to_string(), reason.trim().to_string());
    }
    Ok(known)
}

/// Below SSIM 0.95 (or no SSIM at all) while POV-Ray rendered it.
fn differs(r: &SceneResult) -> bool {
    !matches!(r.class, Class::Good | Class::PovFailed(_))
}

/// Scenes below 0.95 that name no reason: no missing keyword, no error, no known difference.
pub fn unexplained<'a>(results: &'a [SceneResult], known: &Known) -> Vec<&'a SceneResult> {
    results
        .iter()
        .filter(|r| {
            matches!(r.class, Class::Close | Class::Low)
                && r.missing.is_empty()
                && !known.contains_key(&r.name)
        })
        .collect()
}

fn cell(s: &str) -> String {
    s.replace('|', "\\|").replace('\n', " ")
}

/// The Markdown report: summary, ranked missing keywords, common errors, then every scene.
pub fn markdown(results: &[SceneResult], header: &str, known: &Known) -> String {
    let s = summarize(results);
    let mut md = String::new();
    let _ = writeln!(md, "# Conformance with POV-Ray 3.7\n");
    let _ = writeln!(md, "{header}\n");
    let _ = writeln!(md, "**Summary:** {}\n", s.line());
    let _ = writeln!(md, "| class | scenes |\n|---|---|");
    for (label, n) in [
        ("SSIM ≥ 0.95", s.good),
        ("0.80 ≤ SSIM < 0.95", s.close),
        ("SSIM < 0.80", s.low),
        ("lancer error", s.error),
        ("lancer panic", s.panic),
        ("lancer timeout", s.timeout),
        ("POV-Ray failed (not counted)", s.pov_failed),
    ] {
        let _ = writeln!(md, "| {label} | {n} |");
    }
    let _ = writeln!(
        md,
        "\n## Missing keywords\n\nKeywords lancer warned it does not support yet, by the number of scenes below SSIM 0.95 that use them; \"only\" counts the scenes where it is the only one missing.\n\n| rank | keyword | scenes | only |\n|---|---|---|---|"
    );
    for (i, (k, n, only)) in ranked_missing(results).iter().enumerate() {
        let _ = writeln!(md, "| {} | `{}` | {n} | {only} |", i + 1, cell(k));
    }
    let errors = ranked_errors(results);
    if !errors.is_empty() {
        let _ = writeln!(
            md,
            "\n## lancer errors and panics\n\n| scenes | message |\n|---|---|"
        );
        for (m, n) in errors {
            let _ = writeln!(md, "| {n} | {} |", cell(&m));
        }
    }
    let _ = writeln!(
        md,
        "\n## Known differences\n\nScenes below SSIM 0.95 whose difference has a measured reason other than a missing keyword (docs/known-differences.tsv).\n\n| scene | SSIM | reason |\n|---|---|---|"
    );
    for r in results.iter().filter(|r| differs(r)) {
        if let Some(why) = known.get(&r.name) {
            let ssim = r.ssim.map_or(String::new(), |v| format!("{v:.3}"));
            let _ = writeln!(md, "| {} | {ssim} | {} |", cell(&r.name), cell(why));
        }
    }
    let silent = unexplained(results, known);
    let _ = writeln!(
        md,
        "\n## Unexplained differences\n\nScenes below SSIM 0.95 with no missing keyword, no error and no known reason: lancer draws another picture and says nothing. {}\n",
        if silent.is_empty() { "None." } else { "Each is a bug to find." }
    );
    for r in &silent {
        let ssim = r.ssim.map_or(String::new(), |v| format!("{v:.3}"));
        let _ = writeln!(md, "- {} ({ssim})", cell(&r.name));
    }
    let _ = writeln!(
        md,
        "\n## Every scene\n\nTimes are whole-process wall times in seconds; POV-Ray's own phase times are in brackets.\n\n| scene | result | SSIM | lancer s | POV-Ray s | notes |\n|---|---|---|---|---|---|"
    );
    for r in results {
        let ssim = r.ssim.map_or("".to_string(), |v| format!("{v:.3}"));
        let _ = writeln!(
            md,
            "| {} | {} | {ssim} | {:.2} | {:.2} ({:.2}) | {} |",
            cell(&r.name),
            r.class.label(),
            r.lancer_seconds,
            r.pov.seconds,
            r.pov.work_seconds,
            cell(&notes(r, known))
        );
    }
    md
}

fn notes(r: &SceneResult, known: &Known) -> String {
    let mut parts = Vec::new();
    if let Some(why) = known.get(&r.name).filter(|_| differs(r)) {
        parts.push(format!("known: {why}"));
    }
    match &r.class {
        Class::Error(m) | Class::Panic(m) | Class::PovFailed(m) => parts.push(m.clone()),
        _ => {}
    }
    if !r.missing.is_empty() {
        let shown: Vec<&str> = r.missing.iter().take(6).map(String::as_str).collect();
        let more = if r.missing.len() > 6 { ", …" } else { "" };
        parts.push(format!("missing: {}{more}", shown.join(", ")));
    }
    parts.join("; ")
}

/// One row per scene: name, class, ssim, lancer seconds, POV-Ray wall and work seconds,
/// missing keywords (comma-separated), message, known difference (below 0.95 only).
pub fn tsv(results: &[SceneResult], known: &Known) -> String {
    let mut out = String::from(
        "scene\tresult\tssim\tlancer_s\tpovray_s\tpovray_work_s\tmissing\tmessage\tknown\n",
    );
    for r in results {
        let msg = match &r.class {
            Class::Error(m) | Class::Panic(m) | Class::PovFailed(m) => m.as_str(),
            _ => "",
        };
        let why = known
            .get(&r.name)
            .filter(|_| differs(r))
            .map_or("", |w| w.as_str());
        let _ = writeln!(
            out,
            "{}\t{}\t{}\t{:.3}\t{:.3}\t{:.3}\t{}\t{}\t{}",
            r.name,
            r.class.label(),
            r.ssim.map_or(String::new(), |v| format!("{v:.4}")),
            r.lancer_seconds,
            r.pov.seconds,
            r.pov.work_seconds,
            r.missing.join(","),
            msg.replace(['\t', '\n'], " "),
            why
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keywords_from_each_message_shape() {
        let err = "warning: 'media' is not supported by lancer yet and is ignored\n\
                   warning: 'normal (surface perturbation)' is not supported by lancer yet\n\
                   error: #switch is not supported by lancer yet\n\
                   error: the function vturbulence is not supported by lancer yet\n\
                   warning: 'media' is not supported by lancer yet and is ignored\n\
                   warning: 'crand' is random in POV-Ray: lancer's graininess differs\n";
        assert_eq!(
            missing_keywords(err),
            vec![
                "media",
                "normal",
                "#switch",
                "vturbulence",
                "crand (random in POV-Ray)"
            ]
        );
    }

    #[test]
    fn first_error_with_its_place() {
        let err = "warning: x\nerror: undeclared identifier 'Foo'\n  ┌─ /a/b/scene.pov:3:7\n";
        assert_eq!(
            first_error(err),
            "undeclared identifier 'Foo' (scene.pov:3:7)"
        );
    }

    #[test]
    fn pov_error_joins_wrapped_lines_and_times_add_up() {
        let err = "Possible Parse Error: assumed_gamma not specified\n==== [Parsing...] ====\nFile 'x.pov' line 2: Parse Error: No matching } in 'sphere', camera found\n instead\nFatal error in parser: Cannot parse input.\n";
        assert_eq!(
            pov_error(err),
            "File 'x.pov' line 2: Parse Error: No matching } in 'sphere', camera found instead"
        );
        let times = "  Parse Time:       0 hours  0 minutes  0 seconds (0.250 seconds)\n  Trace Time:       0 hours  0 minutes  1 seconds (1.500 seconds)\n";
        assert!((pov_work_seconds(times) - 1.75).abs() < 1e-9);
    }

    #[test]
    fn panic_message_names_the_place() {
        let err = "thread 'main' panicked at src/geom/bvh.rs:10:5:\nindex out of bounds\n";
        assert_eq!(
            panic_message(err, Some(101)),
            "index out of bounds (at src/geom/bvh.rs:10:5)"
        );
    }

    #[test]
    fn known_differences_name_a_reason_and_the_rest_are_listed() {
        let known = parse_known("scene\treason\n# measured\na.pov\tcoincident surfaces\n").unwrap();
        assert_eq!(known["a.pov"], "coincident surfaces");
        assert_eq!(parse_known("x.pov\n").unwrap_err().0, 1);
        assert!(parse_known("x.pov\t \n").is_err());
        let row = |name: &str, class: Class, missing: &[&str]| SceneResult {
            name: name.into(),
            class,
            ssim: Some(0.5),
            lancer_seconds: 0.0,
            pov: super::super::cache::PovResult {
                status: super::super::cache::PovStatus::Ok,
                seconds: 0.0,
                work_seconds: 0.0,
                message: String::new(),
            },
            missing: missing.iter().map(|s| s.to_string()).collect(),
        };
        let results = [
            row("a.pov", Class::Low, &[]),
            row("b.pov", Class::Close, &[]),
            row("c.pov", Class::Low, &["media"]),
            row("d.pov", Class::Good, &[]),
        ];
        let silent: Vec<&str> = unexplained(&results, &known)
            .iter()
            .map(|r| r.name.as_str())
            .collect();
        assert_eq!(silent, ["b.pov"]);
        let md = markdown(&results, "", &known);
        assert!(
            md.contains("| a.pov | 0.500 | coincident surfaces |"),
            "{md}"
        );
        assert!(md.contains("- b.pov (0.500)"), "{md}");
        assert!(tsv(&results, &known).contains("\tcoincident surfaces\n"));
    }
}
