//! `save_file` / `load_file` of the global photons block: the stored photons and the gather
//! radius lancer estimated from them, in lancer's own little-endian format (POV-Ray's files
//! are its own; the manual says the map is view-independent, so a saved map serves every
//! frame of an animation whose photon-relevant geometry does not move).

use super::photon_tree::Photon;

const MAGIC: &[u8; 8] = b"LNCRPH01";

/// The file's bytes for `photons` and the estimated gather `radius`.
pub fn encode(photons: &[Photon], radius: f32) -> Vec<u8> {
    let mut out = Vec::with_capacity(20 + photons.len() * 36);
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&(photons.len() as u64).to_le_bytes());
    out.extend_from_slice(&radius.to_le_bytes());
    for p in photons {
        for v in p.pos.iter().chain(&p.dir).chain(&p.power) {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
    out
}

/// The photons and radius of a file written by `encode`.
pub fn decode(bytes: &[u8]) -> Result<(Vec<Photon>, f32), String> {
    let bad = || "not a lancer photon map (or truncated)".to_string();
    if bytes.len() < 20 || &bytes[..8] != MAGIC {
        return Err(bad());
    }
    let n = u64::from_le_bytes(bytes[8..16].try_into().map_err(|_| bad())?) as usize;
    let radius = f32::from_le_bytes(bytes[16..20].try_into().map_err(|_| bad())?);
    let body = &bytes[20..];
    if body.len() != n.checked_mul(36).ok_or_else(bad)? {
        return Err(bad());
    }
    let f = |i: usize| f32::from_le_bytes([body[i], body[i + 1], body[i + 2], body[i + 3]]);
    let photons = (0..n)
        .map(|k| {
            let b = k * 36;
            Photon {
                pos: [f(b), f(b + 4), f(b + 8)],
                dir: [f(b + 12), f(b + 16), f(b + 20)],
                power: [f(b + 24), f(b + 28), f(b + 32)],
            }
        })
        .collect();
    Ok((photons, radius))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        let ph = vec![
            Photon {
                pos: [1.0, -2.5, 3.25],
                dir: [0.0, -1.0, 0.0],
                power: [0.1, 0.2, 0.3],
            },
            Photon {
                pos: [f32::MAX, 0.0, -0.0],
                dir: [0.6, 0.8, 0.0],
                power: [1e-9, 5.0, 7.0],
            },
        ];
        let (back, r) = decode(&encode(&ph, 0.125)).unwrap();
        assert_eq!(back, ph);
        assert_eq!(r, 0.125);
        assert!(decode(b"LNCRPH01short").is_err());
        assert!(decode(&encode(&ph, 1.0)[..40]).is_err());
    }
}
