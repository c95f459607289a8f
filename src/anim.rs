//! POV-Ray's animation model: which frames a run renders, the clock each frame sees, and the
//! file each frame is written to (`scene01.png` … `scene12.png`). Every frame is parsed anew,
//! as POV-Ray does, so a scene may change anything with `clock`.

use std::path::{Path, PathBuf};

use crate::sdl::ParseOptions;

/// The animation options (`+KFI +KFF +KI +KF +KC +SF +EF +K`), as given; POV-Ray's defaults
/// fill in the rest.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Animation {
    pub initial_frame: Option<i64>,
    pub final_frame: Option<i64>,
    pub initial_clock: Option<f64>,
    pub final_clock: Option<f64>,
    /// `+KC`: the last frame is one step before the first again, for loops.
    pub cyclic: bool,
    /// `+SF`/`+EF`: a frame number, or below 1 a fraction of the frame count.
    pub subset_start: Option<f64>,
    pub subset_end: Option<f64>,
    /// `+STP` (Frame_Step): render every n-th frame of the subset.
    pub step: Option<i64>,
    /// `+K`: the clock of a still picture.
    pub clock: Option<f64>,
}

/// One frame to render: what the scene sees and where the picture goes.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub number: i64,
    pub clock: f64,
    pub clock_delta: f64,
    pub initial_frame: i64,
    pub final_frame: i64,
    pub initial_clock: f64,
    pub final_clock: f64,
    pub output: PathBuf,
}

impl Frame {
    /// Puts the frame's values where the scene language reads them.
    pub fn apply(&self, o: &mut ParseOptions, animated: bool) {
        o.clock = self.clock;
        o.clock_delta = self.clock_delta;
        o.clock_on = animated;
        o.frame_number = self.number;
        o.initial_frame = self.initial_frame;
        o.final_frame = self.final_frame;
        o.initial_clock = self.initial_clock;
        o.final_clock = self.final_clock;
    }
}

impl Animation {
    /// Whether more than a still picture is asked for: a final frame after the first.
    pub fn is_animation(&self) -> bool {
        let first = self.initial_frame.unwrap_or(1);
        self.final_frame.is_some_and(|last| last > first)
    }

    /// The frames to render, in order, writing to names made from `output`. A still picture
    /// is one frame numbered 0 written to `output` itself (its clock from `+K`, POV-Ray's
    /// `clock_on` then set only when `+K` was given).
    pub fn frames(&self, output: &Path) -> Result<Vec<Frame>, String> {
        if !self.is_animation() {
            return Ok(vec![Frame {
                number: 0,
                clock: self.clock.unwrap_or(0.0),
                clock_delta: 0.0,
                initial_frame: 0,
                final_frame: 0,
                initial_clock: 0.0,
                final_clock: 0.0,
                output: output.to_path_buf(),
            }]);
        }
        let first = self.initial_frame.unwrap_or(1);
        let last = self.final_frame.unwrap_or(first);
        let (c0, c1) = (
            self.initial_clock.unwrap_or(0.0),
            self.final_clock.unwrap_or(1.0),
        );
        let steps = (last - first + i64::from(self.cyclic)) as f64;
        let delta = (c1 - c0) / steps;
        // POV-Ray 3.7 turns a fraction into floor(f × frame count) and takes that as a frame
        // number, not an offset from the first frame (checked with +KFI5 +KFF14 +EF0.5: only
        // frame 5).
        let count = (last - first + 1) as f64;
        let frame_of = |v: f64| {
            if v < 1.0 {
                (v * count).floor() as i64
            } else {
                v as i64
            }
        };
        let from = self.subset_start.map_or(first, frame_of).max(first);
        let to = self.subset_end.map_or(last, frame_of).min(last);
        if from > to {
            return Err(format!(
                "the subset of frames {from} to {to} is empty (the animation has frames {first} to {last})"
            ));
        }
        let digits = last.max(1).to_string().len();
        let step = self.step.unwrap_or(1);
        if step < 1 {
            return Err(format!("the frame step must be at least 1, not {step}"));
        }
        Ok((from..=to)
            .step_by(step as usize)
            .map(|n| Frame {
                number: n,
                clock: c0 + (n - first) as f64 * delta,
                clock_delta: delta,
                initial_frame: first,
                final_frame: last,
                initial_clock: c0,
                final_clock: c1,
                output: numbered(output, n, digits),
            })
            .collect())
    }
}

/// `dir/scene.png` → `dir/scene07.png`: the frame number padded to `digits`, before the
/// extension, as POV-Ray names animation frames.
pub fn numbered(output: &Path, n: i64, digits: usize) -> PathBuf {
    let stem = output
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let name = match output.extension() {
        Some(ext) => format!("{stem}{n:0digits$}.{}", ext.to_string_lossy()),
        None => format!("{stem}{n:0digits$}"),
    };
    output.with_file_name(name)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn anim(first: i64, last: i64) -> Animation {
        Animation {
            initial_frame: Some(first),
            final_frame: Some(last),
            ..Animation::default()
        }
    }

    // The expected numbers are what povray 3.7 prints for clock, clock_delta and frame_number
    // with the same options (checked with #debug).

    #[test]
    fn twelve_frames_subset_three_to_four() {
        let a = Animation {
            subset_start: Some(3.0),
            subset_end: Some(4.0),
            ..anim(1, 12)
        };
        let f = a.frames(Path::new("a.png")).unwrap();
        assert_eq!(f.len(), 2);
        assert_eq!(f[0].number, 3);
        assert!((f[0].clock - 2.0 / 11.0).abs() < 1e-12);
        assert!((f[1].clock_delta - 1.0 / 11.0).abs() < 1e-12);
        assert_eq!(f[0].output, PathBuf::from("a03.png"));
        assert_eq!(f[1].output, PathBuf::from("a04.png"));
    }

    #[test]
    fn cyclic_adds_a_step_and_single_digits_stay_unpadded() {
        let a = Animation {
            cyclic: true,
            ..anim(1, 3)
        };
        let f = a.frames(Path::new("out/out.png")).unwrap();
        let clocks: Vec<f64> = f.iter().map(|f| f.clock).collect();
        assert_eq!(clocks, vec![0.0, 1.0 / 3.0, 2.0 / 3.0]);
        assert_eq!(f[2].output, PathBuf::from("out/out3.png"));
    }

    #[test]
    fn clock_range_and_default_first_frame() {
        let a = Animation {
            final_frame: Some(3),
            initial_clock: Some(2.0),
            final_clock: Some(4.0),
            ..Animation::default()
        };
        let f = a.frames(Path::new("a.png")).unwrap();
        assert_eq!(
            f.iter().map(|f| (f.number, f.clock)).collect::<Vec<_>>(),
            vec![(1, 2.0), (2, 3.0), (3, 4.0)]
        );
    }

    #[test]
    fn still_picture_keeps_its_name_and_plus_k_clock() {
        let a = Animation {
            clock: Some(0.7),
            ..Animation::default()
        };
        assert!(!a.is_animation());
        let f = a.frames(Path::new("x.png")).unwrap();
        assert_eq!((f[0].number, f[0].clock), (0, 0.7));
        assert_eq!(f[0].output, PathBuf::from("x.png"));
        assert!(anim(1, 1).frames(Path::new("x.png")).unwrap().len() == 1);
    }

    #[test]
    fn subset_fractions_and_frame_step_as_povray_picks_them() {
        // The frames povray 3.7 wrote for each option set.
        let numbers = |a: Animation| -> Vec<i64> {
            a.frames(Path::new("t.png"))
                .unwrap()
                .iter()
                .map(|f| f.number)
                .collect()
        };
        let sub = |first, last, sf: Option<f64>, ef: Option<f64>, step: Option<i64>| Animation {
            subset_start: sf,
            subset_end: ef,
            step,
            ..anim(first, last)
        };
        assert_eq!(
            numbers(sub(1, 10, Some(0.333), Some(0.667), None)),
            [3, 4, 5, 6]
        );
        assert_eq!(
            numbers(sub(1, 10, Some(0.5), None, None)),
            [5, 6, 7, 8, 9, 10]
        );
        assert_eq!(numbers(sub(1, 10, None, Some(0.25), None)), [1, 2]);
        assert_eq!(numbers(sub(1, 10, None, None, Some(3))), [1, 4, 7, 10]);
        assert_eq!(
            numbers(sub(1, 10, Some(2.0), Some(9.0), Some(3))),
            [2, 5, 8]
        );
        assert_eq!(numbers(sub(1, 10, Some(0.0), Some(1.0), None)), [1]);
        assert_eq!(numbers(sub(5, 14, None, Some(0.5), None)), [5]);
        assert_eq!(numbers(sub(5, 14, Some(0.25), Some(0.75), None)), [5, 6, 7]);
        assert_eq!(numbers(sub(0, 9, Some(0.5), None, None)), [5, 6, 7, 8, 9]);
    }

    #[test]
    fn empty_subset_is_an_error() {
        let a = Animation {
            subset_start: Some(9.0),
            subset_end: Some(4.0),
            ..anim(1, 12)
        };
        assert!(a.frames(Path::new("a.png")).is_err());
    }
}
