//! `lancer._lancer`: the Rust half of the Python module (python/lancer/__init__.py is the
//! other). Renders in-process with the GIL released, hands pictures back as NumPy arrays, and
//! raises `SceneError` with the file, line and column of a scene error. Options are exactly
//! the command line's (POV-Ray switches, INI keys, INI files); configuration files
//! (povray.ini, povray.conf) are not read: a library call depends only on its arguments.

use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;

use lancer::anim::Frame;
use lancer::api::ErrorPlace;
use lancer::cli::{make_job, Job, RenderArgs};
use lancer::render::Film;
use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyReadonlyArray3};
use pyo3::exceptions::{PyException, PyValueError};
use pyo3::prelude::*;

pyo3::create_exception!(_lancer, SceneError, PyException);

/// A scene given as text lives in a directory of its own for the render's length.
struct TempScene(PathBuf);

impl Drop for TempScene {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A render job and the frames it will render.
#[pyclass(module = "lancer._lancer")]
struct Job_ {
    job: Job,
    frames: Vec<Frame>,
    next: usize,
    /// Where a scene given as text was written; its errors name `<string>` instead.
    _temp: Option<TempScene>,
}

fn temp_scene(text: &str) -> PyResult<(PathBuf, TempScene)> {
    use std::sync::atomic::AtomicUsize;
    static N: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "lancer-py-{}-{}",
        std::process::id(),
        N.fetch_add(1, Ordering::Relaxed)
    ));
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("scene.pov");
    std::fs::write(&path, text)?;
    Ok((path, TempScene(dir)))
}

/// Builds a job from the scene (a path, or SDL text when `is_text`) and command-line
/// options, as `lancer` would from its arguments.
#[pyfunction]
#[pyo3(signature = (scene, is_text, options, include_path))]
fn prepare(
    scene: String,
    is_text: bool,
    options: Vec<String>,
    include_path: Vec<PathBuf>,
) -> PyResult<Job_> {
    let (path, temp) = if is_text {
        let (p, t) = temp_scene(&scene)?;
        (p, Some(t))
    } else {
        (PathBuf::from(&scene), None)
    };
    let mut warnings = Vec::new();
    let mut argv = vec!["lancer".to_string()];
    argv.extend(options);
    let argv = lancer::ini::expand(argv, &mut warnings).map_err(PyValueError::new_err)?;
    let mut library_path = include_path;
    if is_text {
        // Text has no directory of its own: its includes are looked for where Python runs.
        library_path.push(std::env::current_dir().unwrap_or_else(|_| PathBuf::from(".")));
    }
    let args = RenderArgs {
        scene: Some(path),
        library_path,
        quiet: true,
        ..RenderArgs::default()
    };
    let mut job = make_job(args, &argv[1..]).map_err(PyValueError::new_err)?;
    job.warnings.extend(warnings);
    let frames = job
        .animation
        .frames(&job.output)
        .map_err(PyValueError::new_err)?;
    Ok(Job_ {
        job,
        frames,
        next: 0,
        _temp: temp,
    })
}

/// A rendered frame: its number, clock, picture and the scene's warnings.
type Rendered = (i64, f64, PyObject, Vec<String>);

enum Failure {
    Scene(ErrorPlace),
    Other(String),
}

/// Parses, builds and renders one frame; no Python object is touched but the callback.
fn render_frame(
    job: &Job,
    f: &Frame,
    progress: Option<&Py<PyAny>>,
) -> (Result<Film, Failure>, Vec<String>) {
    let mut warnings = Vec::new();
    let parsed = lancer::api::parse_file(&job.scene, job.parse_options(f));
    let sources = &parsed.parser.sources;
    warnings.extend(parsed.parser.warnings.iter().map(|w| w.one_line(sources)));
    if let Some(e) = &parsed.error {
        return (Err(Failure::Scene(ErrorPlace::of(e, sources))), warnings);
    }
    let (w, h) = (job.settings.width, job.settings.height);
    let built = lancer::scene::build::build(&parsed.parser.scene, w, h);
    drop(parsed);
    warnings.extend(built.warnings.iter().cloned());
    // The count and the call under one lock, so the callback sees the rows in order and its
    // last call is (total, total) whichever worker finishes last.
    let done = std::sync::Mutex::new(0u64);
    let total = h as u64;
    let report = |n: u64| {
        let mut done = done.lock().unwrap_or_else(|e| e.into_inner());
        *done += n;
        let d = *done;
        if let Some(cb) = progress {
            Python::with_gil(|py| {
                if let Err(e) = cb.call1(py, (d.min(total), total)) {
                    // An exception in the callback cannot stop the render; it is shown.
                    e.print(py);
                }
            });
        }
    };
    let film = lancer::render::render(&built.scene, &job.settings, &report);
    if film.width == 0 {
        return (Err(Failure::Other("empty picture".into())), warnings);
    }
    (Ok(film), warnings)
}

fn to_array(py: Python<'_>, job: &Job, film: &Film, float: bool) -> PyResult<PyObject> {
    let (h, w) = (film.height as usize, film.width as usize);
    let bad = |e: numpy::ndarray::ShapeError| PyValueError::new_err(e.to_string());
    Ok(if float {
        let (data, ch) = lancer::api::linear_f32(film);
        Array3::from_shape_vec((h, w, ch), data)
            .map_err(bad)?
            .into_pyarray(py)
            .into_any()
            .unbind()
    } else {
        let (data, ch) = lancer::api::samples8(film, &job.output_spec, film.alpha.is_some());
        Array3::from_shape_vec((h, w, ch), data)
            .map_err(bad)?
            .into_pyarray(py)
            .into_any()
            .unbind()
    })
}

fn scene_error(py: Python<'_>, e: ErrorPlace) -> PyErr {
    let err = SceneError::new_err(e.one_line.clone());
    let v = err.value(py);
    let _ = v.setattr("file", e.file);
    let _ = v.setattr("line", e.line);
    let _ = v.setattr("column", e.column);
    let _ = v.setattr("message", e.message);
    err
}

#[pymethods]
impl Job_ {
    /// The number of frames (1 for a still picture).
    fn __len__(&self) -> usize {
        self.frames.len()
    }

    /// Warnings about the options.
    #[getter]
    fn option_warnings(&self) -> Vec<String> {
        self.job.warnings.clone()
    }

    /// Renders the next frame with the GIL released: `(frame_number, clock, picture,
    /// warnings)`, or None after the last.
    #[pyo3(signature = (float, progress=None))]
    fn render_next(
        &mut self,
        py: Python<'_>,
        float: bool,
        progress: Option<Py<PyAny>>,
    ) -> PyResult<Option<Rendered>> {
        let Some(f) = self.frames.get(self.next) else {
            return Ok(None);
        };
        self.next += 1;
        let job = &self.job;
        let (film, warnings) = py.allow_threads(|| render_frame(job, f, progress.as_ref()));
        match film {
            Ok(film) => {
                let a = to_array(py, job, &film, float)?;
                Ok(Some((f.number, f.clock, a, warnings)))
            }
            Err(Failure::Scene(mut e)) => {
                if let Some(t) = &self._temp {
                    let tmp = t.0.join("scene.pov").display().to_string();
                    if e.file.as_deref() == Some(tmp.as_str()) {
                        e.one_line = e.one_line.replacen(&tmp, "<string>", 1);
                        e.file = Some("<string>".into());
                    }
                }
                Err(scene_error(py, e))
            }
            Err(Failure::Other(e)) => Err(PyValueError::new_err(e)),
        }
    }
}

/// SSIM of two float32 RGB pictures in [0, 1] of the same size, as `lancer compare` computes
/// it: `(ssim, psnr, worst_tile_ssim)`.
#[pyfunction]
fn compare_rgb(a: PyReadonlyArray3<f32>, b: PyReadonlyArray3<f32>) -> PyResult<(f64, f64, f64)> {
    let pic = |x: &PyReadonlyArray3<f32>| -> PyResult<lancer::ssim::Picture> {
        let view = x.as_array();
        let s = view.shape();
        if s[2] != 3 {
            return Err(PyValueError::new_err("expected H x W x 3"));
        }
        Ok(lancer::ssim::Picture {
            width: s[1] as u32,
            height: s[0] as u32,
            rgb: view.iter().copied().collect(),
        })
    };
    let (pa, pb) = (pic(&a)?, pic(&b)?);
    if (pa.width, pa.height) != (pb.width, pb.height) {
        return Err(PyValueError::new_err(format!(
            "the pictures differ in size: {}x{} and {}x{}",
            pa.width, pa.height, pb.width, pb.height
        )));
    }
    let c = lancer::compare::compare(&pa, &pb).map_err(PyValueError::new_err)?;
    Ok((c.ssim, c.psnr, c.worst_tile.2))
}

/// A picture file as `lancer compare` reads it: float32 RGB in [0, 1], H x W x 3.
#[pyfunction]
fn load_rgb(py: Python<'_>, path: PathBuf) -> PyResult<PyObject> {
    let p = lancer::ssim::Picture::load(Path::new(&path)).map_err(PyValueError::new_err)?;
    let a = Array3::from_shape_vec((p.height as usize, p.width as usize, 3), p.rgb)
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    Ok(a.into_pyarray(py).into_any().unbind())
}

/// Runs the `lancer` command with `argv` (program name first) in this process; returns its
/// exit code.
#[pyfunction]
fn main(py: Python<'_>, argv: Vec<String>) -> u8 {
    py.allow_threads(|| lancer::app::run_status(argv))
}

#[pymodule]
fn _lancer(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("SceneError", m.py().get_type::<SceneError>())?;
    m.add_class::<Job_>()?;
    m.add_function(wrap_pyfunction!(prepare, m)?)?;
    m.add_function(wrap_pyfunction!(compare_rgb, m)?)?;
    m.add_function(wrap_pyfunction!(load_rgb, m)?)?;
    m.add_function(wrap_pyfunction!(main, m)?)?;
    Ok(())
}
