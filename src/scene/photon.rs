//! Photon settings as written: the global `photons { }` block, an object's and a light's
//! (manual 3.4.4.4), with POV-Ray's defaults. render::photons shoots and gathers with them.

/// `global_settings { photons { ... } }`.
#[derive(Clone, Debug, PartialEq)]
pub struct PhotonSettings {
    /// `spacing`: the distance between photons on surfaces at a target's distance.
    pub spacing: Option<f64>,
    /// `count`: the number of photons to shoot instead (a spacing is derived from it).
    pub count: Option<f64>,
    pub gather_min: u32,
    pub gather_max: u32,
    pub jitter: f64,
    /// None: the scene's own max_trace_level and adc_bailout.
    pub max_trace_level: Option<u32>,
    pub adc_bailout: Option<f64>,
    pub autostop: f64,
    /// `expand_thresholds`: the largest accepted rise in density when a search is widened,
    /// and the count below which the widened search is taken anyway.
    pub expand_increase: f64,
    pub expand_min: u32,
    /// `radius`: the gather radius (None: estimated from the photons) and its multiplier.
    pub radius: Option<f64>,
    pub radius_mult: f64,
    /// `save_file` / `load_file`: where the photon map is written after shooting, or read
    /// from instead of shooting.
    pub save_file: Option<String>,
    pub load_file: Option<String>,
}

impl Default for PhotonSettings {
    fn default() -> Self {
        PhotonSettings {
            spacing: None,
            count: None,
            gather_min: 20,
            gather_max: 100,
            jitter: 0.4,
            max_trace_level: None,
            adc_bailout: None,
            autostop: 1.0,
            expand_increase: 0.2,
            expand_min: 40,
            radius: None,
            radius_mult: 1.0,
            save_file: None,
            load_file: None,
        }
    }
}

/// An object's `photons { }` flags.
pub mod flags {
    pub const TARGET: u8 = 1;
    pub const REFRACTION: u8 = 2;
    pub const REFLECTION: u8 = 4;
    /// `collect off`: no photons are stored on or gathered from the object.
    pub const NO_COLLECT: u8 = 8;
    pub const PASS_THROUGH: u8 = 16;
    /// `pass_through off` written: a `no_shadow` object then still stops photons.
    pub const PASS_THROUGH_OFF: u8 = 32;
}

/// An object's `photons { target [mult] refraction reflection collect pass_through }`.
/// Three bytes: every object description carries one (tests/memory_layout.rs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObjectPhotons {
    pub flags: u8,
    /// `target Float`: the spacing multiplier for photons shot at this object, in 1/1024ths
    /// (1/1024 to 64; finer steps change no picture).
    mult: u16,
}

impl Default for ObjectPhotons {
    fn default() -> Self {
        ObjectPhotons {
            flags: 0,
            mult: 1024,
        }
    }
}

impl ObjectPhotons {
    pub fn spacing_mult(&self) -> f32 {
        self.mult as f32 / 1024.0
    }

    pub fn set_spacing_mult(&mut self, m: f64) {
        self.mult = (m * 1024.0).round().clamp(1.0, 65535.0) as u16;
    }
}

/// A light's `photons { refraction reflection area_light }`. Measured with povray: a light
/// without the block shoots photons that refract and reflect (the manual's table says off).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightPhotons {
    pub refraction: bool,
    pub reflection: bool,
    pub area_light: bool,
}

impl Default for LightPhotons {
    fn default() -> Self {
        LightPhotons {
            refraction: true,
            reflection: true,
            area_light: false,
        }
    }
}
