//! `density_file df3 "file" [interpolate N]`: a 3-D grid of densities over the unit cube
//! (manual 3.4.8.4 "Density_file"). A DF3 file is three big-endian 16-bit sizes (x, y, z)
//! followed by the voxels, x fastest, each 1, 2 or 4 big-endian bytes (the size that
//! fills the file), read as a fraction of that size's maximum.

use std::path::Path;

use crate::math::DVec3;

#[derive(Clone, Debug)]
pub struct Df3 {
    pub size: [usize; 3],
    pub values: Vec<f32>,
    /// 0 nearest voxel, 1 trilinear (2, tricubic, is read as trilinear).
    pub interpolate: u32,
}

impl Df3 {
    pub fn load(path: &Path, interpolate: u32) -> Result<Df3, String> {
        let data =
            std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        if data.len() < 6 {
            return Err(format!("{} is too short for a DF3 file", path.display()));
        }
        let dim = |i: usize| u16::from_be_bytes([data[2 * i], data[2 * i + 1]]) as usize;
        let size = [dim(0), dim(1), dim(2)];
        let n = size[0] * size[1] * size[2];
        let body = &data[6..];
        let bytes = body.len().checked_div(n).unwrap_or(0);
        let values: Vec<f32> = match bytes {
            0 => Vec::new(),
            1 => body[..n].iter().map(|&b| b as f32 / 255.0).collect(),
            2 | 3 => body[..2 * n]
                .chunks_exact(2)
                .map(|c| u16::from_be_bytes([c[0], c[1]]) as f32 / 65535.0)
                .collect(),
            _ => body[..4 * n]
                .chunks_exact(4)
                .map(|c| {
                    (u32::from_be_bytes([c[0], c[1], c[2], c[3]]) as f64 / u32::MAX as f64) as f32
                })
                .collect(),
        };
        if values.len() != n {
            return Err(format!(
                "{} holds fewer voxels than its {}x{}x{} header says",
                path.display(),
                size[0],
                size[1],
                size[2]
            ));
        }
        Ok(Df3 {
            size,
            values,
            interpolate,
        })
    }

    fn at(&self, x: usize, y: usize, z: usize) -> f64 {
        self.values[(z * self.size[1] + y) * self.size[0] + x] as f64
    }

    /// The density at `p`; 0 outside the unit cube.
    pub fn eval(&self, p: DVec3) -> f64 {
        if self.values.is_empty() || !(0.0..1.0).contains(&p.x) || !(0.0..1.0).contains(&p.y) {
            return 0.0;
        }
        if !(0.0..1.0).contains(&p.z) {
            return 0.0;
        }
        let [nx, ny, nz] = self.size;
        if self.interpolate == 0 {
            let i = |v: f64, n: usize| ((v * n as f64) as usize).min(n - 1);
            return self.at(i(p.x, nx), i(p.y, ny), i(p.z, nz));
        }
        // Trilinear between voxel centres, clamped at the faces.
        let axis = |v: f64, n: usize| {
            let f = (v * n as f64 - 0.5).clamp(0.0, (n - 1) as f64);
            let i = (f as usize).min(n.saturating_sub(2));
            (i, (i + 1).min(n - 1), f - i as f64)
        };
        let (x0, x1, fx) = axis(p.x, nx);
        let (y0, y1, fy) = axis(p.y, ny);
        let (z0, z1, fz) = axis(p.z, nz);
        let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
        let plane = |z: usize| {
            lerp(
                lerp(self.at(x0, y0, z), self.at(x1, y0, z), fx),
                lerp(self.at(x0, y1, z), self.at(x1, y1, z), fx),
                fy,
            )
        };
        lerp(plane(z0), plane(z1), fz)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_bytes_and_interpolates() {
        let dir = std::env::temp_dir().join(format!("lancer_df3_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("two.df3");
        // 2x1x1, one byte per voxel: 0 and 255.
        std::fs::write(&path, [0, 2, 0, 1, 0, 1, 0, 255]).unwrap();
        let d = Df3::load(&path, 0).unwrap();
        assert_eq!(d.eval(DVec3::new(0.25, 0.5, 0.5)), 0.0);
        assert_eq!(d.eval(DVec3::new(0.75, 0.5, 0.5)), 1.0);
        assert_eq!(d.eval(DVec3::new(1.5, 0.5, 0.5)), 0.0);
        let d = Df3::load(&path, 1).unwrap();
        assert!((d.eval(DVec3::new(0.5, 0.5, 0.5)) - 0.5).abs() < 1e-9);
        std::fs::remove_dir_all(&dir).ok();
    }
}
