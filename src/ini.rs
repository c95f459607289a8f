//! POV-Ray INI files: `Key=Value` lines, `;` comments, `[Section]` labels selected with
//! `file.ini[Section]`, switches on their own lines and INI files naming other INI files. Each
//! INI file on the command line is replaced, where it stands, by the switches it amounts to,
//! so options and INI files mixed in any order apply in order and the later one wins, as in
//! POV-Ray.

use std::path::{Path, PathBuf};

/// How deep INI files may name other INI files (POV-Ray's limit is ten).
const MAX_DEPTH: usize = 10;

/// Replaces every INI file argument (`opts.ini`, `opts.ini[Section]`, or `opts` when
/// `opts.ini` exists) by the switches it holds. Warnings go to `warnings`.
pub fn expand(args: Vec<String>, warnings: &mut Vec<String>) -> Result<Vec<String>, String> {
    let mut out = Vec::with_capacity(args.len());
    for (i, a) in args.into_iter().enumerate() {
        // POV-Ray takes INI-style `Key=Value` on the command line too (`Declare=Size=2`).
        if i > 0 && !a.starts_with(['+', '-']) && a.contains('=') {
            if let Some((key, value)) = a.split_once('=') {
                match switch_for(key.trim(), unquote(value.trim())) {
                    Ok(Some(s)) => out.push(s),
                    Ok(None) => {}
                    Err(w) => warnings.push(w),
                }
                continue;
            }
        }
        match (i > 0).then(|| ini_reference(&a, Path::new("."))).flatten() {
            Some((path, section)) => read(&path, section.as_deref(), 0, &mut out, warnings)?,
            None => out.push(a),
        }
    }
    Ok(out)
}

/// The switches one INI file holds (its unlabelled top), as for a main INI file.
pub fn expand_file(path: &Path, warnings: &mut Vec<String>) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    read(path, None, 0, &mut out, warnings)?;
    Ok(out)
}

/// `name.ini[Section]` → the file and the section, when the argument names an INI file.
fn ini_reference(arg: &str, dir: &Path) -> Option<(PathBuf, Option<String>)> {
    if arg.starts_with(['+', '-']) {
        return None;
    }
    let (name, section) = match arg.find('[') {
        Some(i) if arg.ends_with(']') => (&arg[..i], Some(arg[i + 1..arg.len() - 1].to_string())),
        _ => (arg, None),
    };
    let path = dir.join(name);
    let is_ini = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("ini"));
    if is_ini {
        return Some((path, section));
    }
    // POV-Ray assumes .ini for a bare name it cannot otherwise place.
    let with_ext = dir.join(format!("{name}.ini"));
    (path.extension().is_none() && with_ext.is_file()).then_some((with_ext, section))
}

fn read(
    path: &Path,
    section: Option<&str>,
    depth: usize,
    out: &mut Vec<String>,
    warnings: &mut Vec<String>,
) -> Result<(), String> {
    if depth >= MAX_DEPTH {
        return Err(format!(
            "{}: INI files nested more than {MAX_DEPTH} deep",
            path.display()
        ));
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the INI file {}: {e}", path.display()))?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let wanted = section.map(str::to_ascii_lowercase);
    // Without a section only the unlabelled top is read; with one, only that section.
    let mut active = wanted.is_none();
    let mut found = wanted.is_none();
    for (n, raw) in text.lines().enumerate() {
        let place = format!("{}:{}", path.display(), n + 1);
        let line = strip_comment(raw).trim();
        if line.is_empty() {
            continue;
        }
        if let Some(label) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
            active = wanted.as_deref() == Some(label.trim().to_ascii_lowercase().as_str());
            found |= active;
            continue;
        }
        if !active {
            continue;
        }
        if line.starts_with(['+', '-']) {
            out.extend(line.split_whitespace().map(String::from));
        } else if let Some((key, value)) = line.split_once('=') {
            let value = unquote(value.trim());
            match switch_for(key.trim(), value) {
                Ok(Some(s)) => out.push(s),
                Ok(None) => {}
                Err(w) => warnings.push(format!("{place}: {w}")),
            }
        } else if let Some((p, s)) = ini_reference(line, dir) {
            read(&p, s.as_deref(), depth + 1, out, warnings)?;
        } else {
            return Err(format!(
                "{place}: '{line}' is neither Key=Value, a switch nor an INI file"
            ));
        }
    }
    if !found {
        return Err(format!(
            "{}: no section [{}]",
            path.display(),
            section.unwrap_or("")
        ));
    }
    Ok(())
}

fn strip_comment(line: &str) -> &str {
    // A ';' inside quotes is part of a file name.
    let mut quote = None;
    for (i, c) in line.char_indices() {
        match (c, quote) {
            ('"' | '\'', None) => quote = Some(c),
            (c, Some(q)) if c == q => quote = None,
            (';', None) => return &line[..i],
            _ => {}
        }
    }
    line
}

fn unquote(v: &str) -> &str {
    for q in ['"', '\''] {
        if let Some(inner) = v.strip_prefix(q).and_then(|r| r.strip_suffix(q)) {
            return inner;
        }
    }
    v
}

fn truthy(v: &str) -> Option<bool> {
    match v.to_ascii_lowercase().as_str() {
        "on" | "true" | "yes" | "1" => Some(true),
        "off" | "false" | "no" | "0" => Some(false),
        _ => None,
    }
}

/// The switch an INI `Key=Value` line stands for, `None` for options that change nothing
/// lancer makes, or a warning for those it does not support (shell-out commands are never
/// run).
fn switch_for(key: &str, value: &str) -> Result<Option<String>, String> {
    let k = key.to_ascii_lowercase();
    let flag = |sw: &str| -> Result<Option<String>, String> {
        match truthy(value) {
            Some(on) => Ok(Some(format!("{}{sw}", if on { '+' } else { '-' }))),
            None => Err(format!("{key}={value}: expected on or off")),
        }
    };
    let with = |sw: &str| Ok(Some(format!("+{sw}{value}")));
    match k.as_str() {
        "input_file_name" | "input_file" => with("I"),
        "output_file_name" | "output_file" => with("O"),
        "library_path" => with("L"),
        "width" => with("W"),
        "height" => with("H"),
        "work_threads" => with("WT"),
        "antialias" => flag("A"),
        "antialias_threshold" => with("A"),
        "antialias_depth" => with("R"),
        "render_block_size" => with("BS"),
        "sampling_method" => with("AM"),
        "antialias_gamma" => with("AG"),
        "output_alpha" => flag("UA"),
        "jitter" => flag("J"),
        "jitter_amount" => with("J"),
        "quality" => with("Q"),
        "initial_frame" => with("KFI"),
        "final_frame" => with("KFF"),
        "initial_clock" => with("KI"),
        "final_clock" => with("KF"),
        "clock" => with("K"),
        "cyclic_animation" => flag("KC"),
        "subset_start_frame" => with("SF"),
        "subset_end_frame" => with("EF"),
        "frame_step" => with("STP"),
        "version" => with("MV"),
        "include_header" => with("HI"),
        "continue_trace" => flag("C"),
        "start_row" => with("SR"),
        "end_row" => with("ER"),
        "start_column" => with("SC"),
        "end_column" => with("EC"),
        "output_file_type" => Ok(Some(format!("+F{value}"))),
        "output_to_file" => flag("F"),
        "declare" => match value.split_once('=') {
            Some((name, v)) if v.trim().parse::<f64>().is_ok() => {
                Ok(Some(format!("+Declare={}={}", name.trim(), v.trim())))
            }
            _ => Err(format!("{key}={value}: expected Declare=Name=number")),
        },
        "dither" => flag("TH"),
        // No switch of their own: passed on as `+Key=value` for cli.rs to read.
        "bits_per_color" | "file_gamma" | "dither_method" | "compression" => {
            Ok(Some(format!("+{key}={value}")))
        }
        // Display, pause, verbosity, statistics and text streams do not change the picture.
        // (Debian's povray.ini, read as povray reads it, says Display=On: a window for every
        // render would be no service; +D on the command line opens one.)
        "display"
        | "pause_when_done"
        | "verbose"
        | "test_abort"
        | "test_abort_count"
        | "display_gamma"
        | "draw_vistas"
        | "preview_start_size"
        | "preview_end_size"
        | "all_console"
        | "debug_console"
        | "fatal_console"
        | "render_console"
        | "statistic_console"
        | "warning_console"
        | "all_file"
        | "debug_file"
        | "fatal_file"
        | "render_file"
        | "statistic_file"
        | "warning_file"
        | "create_ini"
        | "bounding"
        | "bounding_threshold"
        | "light_buffer"
        | "vista_buffer"
        | "remove_bounds"
        | "split_unions"
        | "histogram_type"
        | "histogram_name"
        | "histogram_grid_size"
        | "video_mode"
        | "palette"
        | "buffer_output"
        | "buffer_size"
        | "field_render"
        | "odd_field"
        | "max_image_buffer_memory"
        | "render_pattern"
        | "render_block_step"
        | "warning_level"
        // Preview-only, and lancer's radiosity is always reproducible (docs/radiosity.md).
        | "radiosity_vain_pretrace"
        | "high_reproducibility" => Ok(None),
        "pre_scene_command"
        | "pre_frame_command"
        | "post_scene_command"
        | "post_frame_command"
        | "user_abort_command"
        | "fatal_error_command"
        | "pre_scene_return"
        | "pre_frame_return"
        | "post_scene_return"
        | "post_frame_return"
        | "user_abort_return"
        | "fatal_error_return" => Err(format!(
            "{key}: lancer never runs shell commands from INI files; ignored"
        )),
        _ => Err(format!(
            "{key} is not supported by lancer yet and is ignored"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tmp(name: &str, text: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("lancer-ini-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        let p = d.join(name);
        std::fs::write(&p, text).unwrap();
        p
    }

    fn expand_one(arg: &str) -> (Vec<String>, Vec<String>) {
        let mut w = Vec::new();
        let out = expand(vec!["lancer".into(), arg.into()], &mut w).unwrap();
        (out[1..].to_vec(), w)
    }

    #[test]
    fn keys_switches_comments_and_shell_commands() {
        let p = tmp(
            "a.ini",
            "; a comment\nInput_File_Name=\"my;scene.pov\" ; trailing\nAntialias=On\nAntialias_Threshold=0.3\n+W80 +H60\nInitial_Frame=1\nfinal_frame=20\nCyclic_Animation=on\nPost_Frame_Command=rm -rf /\nPause_when_Done=off\n",
        );
        let (out, w) = expand_one(p.to_str().unwrap());
        assert_eq!(
            out,
            vec![
                "+Imy;scene.pov",
                "+A",
                "+A0.3",
                "+W80",
                "+H60",
                "+KFI1",
                "+KFF20",
                "+KC"
            ]
        );
        assert_eq!(w.len(), 1);
        assert!(w[0].contains("never runs shell commands"), "{w:?}");
    }

    #[test]
    fn sections_nesting_and_bare_names() {
        let inner = tmp(
            "res.ini",
            "+W120 +H100\n[Low]\n+W80 +H60\n[Really High]\n+W800 +H600\n",
        );
        let (top, _) = expand_one(inner.to_str().unwrap());
        assert_eq!(top, vec!["+W120", "+H100"]);
        let (high, _) = expand_one(&format!("{}[really high]", inner.display()));
        assert_eq!(high, vec!["+W800", "+H600"]);
        let outer = tmp("outer.ini", "Width=10\nres[Low]\nHeight=5\n");
        let (out, _) = expand_one(outer.to_str().unwrap());
        assert_eq!(out, vec!["+W10", "+W80", "+H60", "+H5"]);
        let bare = outer.with_extension("");
        let (out, _) = expand_one(bare.to_str().unwrap());
        assert_eq!(out.len(), 4);
        let mut w = Vec::new();
        assert!(expand(
            vec!["lancer".into(), format!("{}[Nope]", inner.display())],
            &mut w
        )
        .unwrap_err()
        .contains("no section"));
    }

    #[test]
    fn file_output_keys() {
        let p = tmp(
            "out.ini",
            "Output_File_Type=T\nBits_Per_Color=12\nFile_Gamma=sRGB\nDither=on\nDither_Method=b2\nCompression=90\nDisplay_Gamma=2.2\n",
        );
        let (out, w) = expand_one(p.to_str().unwrap());
        assert_eq!(
            out,
            vec![
                "+FT",
                "+Bits_Per_Color=12",
                "+File_Gamma=sRGB",
                "+TH",
                "+Dither_Method=b2",
                "+Compression=90"
            ]
        );
        assert!(w.is_empty(), "{w:?}");
    }

    #[test]
    fn endless_nesting_is_an_error() {
        let p = tmp("self.ini", "self.ini\n");
        let mut w = Vec::new();
        let e = expand(vec!["lancer".into(), p.display().to_string()], &mut w).unwrap_err();
        assert!(e.contains("nested"), "{e}");
    }
}
