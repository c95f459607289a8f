//! Patterned textures (`texture { checker texture {..} texture {..} }`, `texture_map`, `tiles`):
//! the colour and finish one texture layer has at a point.
//!
//! Block patterns pick one listed texture. Between two `texture_map` entries POV-Ray shades
//! both textures, each with its own finish, and mixes the results by the entries' weights; the
//! shading code does the same with the parts `blend` hands it.

use crate::color::Rgbft;
use crate::math::{DVec3, Transform};
use crate::scene::desc::{Texture, TextureEntries};
use crate::scene::pattern::PatternKind;

use super::{normal, pattern, pigment};

/// Calls `f(colour, texture, space, weight)` for each plain texture that `tex` (one layer) is
/// made of at world point `p`: itself when it is plain, one listed texture for a block
/// pattern, the one or two `texture_map` entries around the pattern's value (nested maps
/// recursively). `space` takes the plain texture's parent space to the world (its normal is
/// relative to it). The weights add up to `weight`; `quick` uses quick colours. `uv` is the
/// surface's (u, v, 0) where it has one, which `uv_mapping` textures and pigments use
/// instead of `p`.
pub fn blend(
    tex: &Texture,
    p: DVec3,
    uv: Option<DVec3>,
    quick: bool,
    weight: f64,
    f: &mut dyn FnMut(Rgbft, &Texture, &Transform, f64),
) {
    blend_in(tex, p, uv, &crate::math::IDENTITY, quick, weight, f)
}

fn blend_in(
    tex: &Texture,
    p: DVec3,
    uv: Option<DVec3>,
    space: &Transform,
    quick: bool,
    weight: f64,
    f: &mut dyn FnMut(Rgbft, &Texture, &Transform, f64),
) {
    // From a uv-mapped texture down, everything is evaluated at the uv point.
    let p = match uv {
        Some(uvp) if tex.uv_mapping => uvp,
        _ => p,
    };
    let Some(tp) = &tex.pattern else {
        f(plain_colour(tex, p, &uv, space, quick), tex, space, weight);
        return;
    };
    // Below a uv-mapped texture the uv point has become the point and goes through the
    // pattern's transform like any other.
    let uv_inner = if tex.uv_mapping { uv.map(|_| p) } else { uv };
    let (lp, inner);
    let space = if tp.transform.is_identity() {
        lp = p;
        space
    } else {
        lp = tp.transform.inv_point(p);
        inner = tp.transform.then(space);
        &inner
    };
    // The entries see the warped point (measured: see `pattern::warped`).
    let q = pattern::warped(&tp.pattern, lp);
    let blend = |t: &Texture, w: f64, f: &mut dyn FnMut(Rgbft, &Texture, &Transform, f64)| {
        blend_in(t, q, uv_inner, space, quick, w, f)
    };
    match &tp.entries {
        TextureEntries::List(items) => {
            let i = pattern::index_warped(&tp.pattern, q).min(items.len().saturating_sub(1));
            if let Some(t) = items.get(i) {
                blend(t, weight, f);
            }
        }
        TextureEntries::Map(map) if matches!(tp.pattern.kind, PatternKind::Average) => {
            let total: f64 = map.iter().map(|e| e.0).sum();
            if total != 0.0 {
                for (w, t) in map {
                    blend(t, weight * w / total, f);
                }
            }
        }
        TextureEntries::Map(map) => {
            let v = pattern::value_warped(&tp.pattern, q);
            let (Some(first), Some(last)) = (map.first(), map.last()) else {
                return;
            };
            if v <= first.0 {
                return blend(&first.1, weight, f);
            }
            for w in map.windows(2) {
                let ((va, ta), (vb, tb)) = (&w[0], &w[1]);
                if v <= *vb {
                    let span = vb - va;
                    if span <= 0.0 {
                        return blend(tb, weight, f);
                    }
                    let t = (v - va) / span;
                    if t < 1.0 {
                        blend(ta, weight * (1.0 - t), f);
                    }
                    if t > 0.0 {
                        blend(tb, weight * t, f);
                    }
                    return;
                }
            }
            blend(&last.1, weight, f)
        }
    }
}

/// A plain texture's colour at world point `p`, as `blend` hands it on (`space` as there):
/// what shading calls for a plain layer without going through `blend`'s callback.
///
/// `uv` by reference, its tag read alone: passed by value it was copied by 16-byte loads
/// over the 8-byte tag store just made (a store-forwarding stall on every patterned hit).
pub fn plain_colour(
    tex: &Texture,
    p: DVec3,
    uv: &Option<DVec3>,
    space: &Transform,
    quick: bool,
) -> Rgbft {
    let p = match uv {
        Some(uvp) if tex.uv_mapping => *uvp,
        _ => p,
    };
    if let (Some(q), true) = (tex.pigment.quick, quick) {
        return q;
    }
    // Measured: a slope or aoi pigment sees its own texture's perturbed normal. The surface
    // is only read (a thread-local) for such a pigment under such a normal.
    if let Some(nd) = tex.normal.as_deref() {
        if pigment::uses_surface(&tex.pigment) && normal::perturbs(Some(nd)) {
            if let Some(s) = pattern::surface() {
                let pn = normal::perturb_in(nd, space, p, s.normal);
                pattern::set_surface(Some(pattern::Surface { normal: pn, ..s }));
                let c = pigment::eval(&tex.pigment, pigment_point(tex, p, *uv));
                pattern::set_surface(Some(s));
                return c;
            }
        }
    }
    pigment::eval(&tex.pigment, pigment_point(tex, p, *uv))
}

/// Whether some plain texture `tex` (one layer) can be made of has a reflection.
pub fn may_reflect(tex: &Texture) -> bool {
    match tex.pattern.as_deref().map(|tp| &tp.entries) {
        None => !tex.finish.reflection.is_zero(),
        Some(TextureEntries::List(items)) => items.iter().any(may_reflect),
        Some(TextureEntries::Map(map)) => map.iter().any(|(_, t)| may_reflect(t)),
    }
}

/// Whether any layer or part of `tex` takes light from light sources: a finish with diffuse,
/// phong or specular not zero (`Tracer::layer_light` adds nothing per light otherwise). A
/// sky dome's `finish { ambient 1 diffuse 0 }` does not, so its hits need no shadow rays.
pub fn lit_by_lights(tex: &Texture) -> bool {
    tex.layers().any(|t| {
        let f = &t.finish;
        f.diffuse != 0.0
            || f.phong != 0.0
            || f.specular != 0.0
            || match t.pattern.as_deref().map(|tp| &tp.entries) {
                None => false,
                Some(TextureEntries::List(items)) => items.iter().any(lit_by_lights),
                Some(TextureEntries::Map(map)) => map.iter().any(|(_, t)| lit_by_lights(t)),
            }
    })
}

/// Where a plain texture's pigment is evaluated: its uv point if it is uv-mapped.
fn pigment_point(tex: &Texture, p: DVec3, uv: Option<DVec3>) -> DVec3 {
    match uv {
        Some(uvp) if tex.pigment.uv_mapping => uvp,
        _ => p,
    }
}

/// The colour alone (unlit pictures, light passing through in shadow rays).
pub fn color_at(tex: &Texture, p: DVec3, uv: Option<DVec3>, quick: bool) -> Rgbft {
    if tex.pattern.is_none() && !quick {
        return pigment::eval(&tex.pigment, pigment_point(tex, p, uv));
    }
    let mut sum = [0.0; 5];
    blend(tex, p, uv, quick, 1.0, &mut |c, _, _, w| {
        for (s, v) in sum.iter_mut().zip(c.to_array()) {
            *s += v * w;
        }
    });
    Rgbft::from_array(sum)
}
