//! Colours as POV-Ray carries them: red, green, blue plus filter and transmit.

use glam::DVec3;

#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Rgbft {
    pub rgb: DVec3,
    pub filter: f64,
    pub transmit: f64,
}

impl Rgbft {
    pub const BLACK: Rgbft = Rgbft {
        rgb: DVec3::ZERO,
        filter: 0.0,
        transmit: 0.0,
    };

    pub fn new(r: f64, g: f64, b: f64, filter: f64, transmit: f64) -> Rgbft {
        Rgbft {
            rgb: DVec3::new(r, g, b),
            filter,
            transmit,
        }
    }
    pub fn rgb(rgb: DVec3) -> Rgbft {
        Rgbft {
            rgb,
            filter: 0.0,
            transmit: 0.0,
        }
    }
    pub fn from_array(a: [f64; 5]) -> Rgbft {
        Rgbft::new(a[0], a[1], a[2], a[3], a[4])
    }
    pub fn to_array(self) -> [f64; 5] {
        [
            self.rgb.x,
            self.rgb.y,
            self.rgb.z,
            self.filter,
            self.transmit,
        ]
    }
    pub fn lerp(self, o: Rgbft, f: f64) -> Rgbft {
        Rgbft {
            rgb: self.rgb + (o.rgb - self.rgb) * f,
            filter: self.filter + (o.filter - self.filter) * f,
            transmit: self.transmit + (o.transmit - self.transmit) * f,
        }
    }
    pub fn is_opaque(&self) -> bool {
        self.filter <= 0.0 && self.transmit <= 0.0
    }
    /// The share of the surface's own colour that shows: 1 − filter − transmit (POV-Ray lets
    /// it go negative; callers that weight light by it clamp).
    pub fn opacity(&self) -> f64 {
        1.0 - self.filter - self.transmit
    }
    /// What light passing through becomes: filtered by the colour, plus the plain transmit.
    pub fn transmitted(&self) -> DVec3 {
        self.rgb * self.filter + DVec3::splat(self.transmit)
    }
}
