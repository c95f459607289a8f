//! TrueType fonts for the `text` object: loading (once per file per process), glyph outlines as
//! y-monotone quadratic pieces, and POV-Ray 3.7's rules for placing a string's glyphs.
//!
//! Reading the font file is left to the `ttf-parser` crate (cmap, hmtx, kern and glyf tables,
//! TrueType collections); this module only turns what it gives into geometry. Coordinates are
//! in em units: font units divided by the font's units per em, which is what POV-Ray does
//! (timrom's "H", 711 of 1000 units wide, is 0.711 wide in POV-Ray's `max_extent`).

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};

use glam::DVec2;

use super::glyph_bands::Bands;
use ttf_parser::{Face, GlyphId, OutlineBuilder, PlatformId};

/// One y-monotone quadratic Bézier piece of a glyph contour, `p0 → p1` with control `c`
/// (a straight segment has `c` at its midpoint, which keeps it exactly linear in s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    pub p0: DVec2,
    pub c: DVec2,
    pub p1: DVec2,
    /// Bounds of the three control points, which contain the curve.
    pub min: DVec2,
    pub max: DVec2,
}

impl Piece {
    fn new(p0: DVec2, c: DVec2, p1: DVec2) -> Piece {
        Piece {
            p0,
            c,
            p1,
            min: p0.min(c).min(p1),
            max: p0.max(c).max(p1),
        }
    }

    pub fn at(&self, s: f64) -> DVec2 {
        let r = 1.0 - s;
        self.p0 * (r * r) + self.c * (2.0 * r * s) + self.p1 * (s * s)
    }

    /// Direction of travel at `s`; the chord where the curve has none (a control point on an
    /// end point).
    pub fn tangent(&self, s: f64) -> DVec2 {
        let t = (self.c - self.p0) * (2.0 * (1.0 - s)) + (self.p1 - self.c) * (2.0 * s);
        if t.length_squared() > 1e-24 {
            t
        } else {
            self.p1 - self.p0
        }
    }

    /// The signed number of times this piece crosses the half-line from `q` towards +x:
    /// +1 going up, -1 going down. Pieces are y-monotone, so there is at most one crossing;
    /// the half-open y range counts a vertex shared by two pieces once.
    fn winding(&self, q: DVec2) -> i32 {
        let (lo, hi, dir) = if self.p0.y < self.p1.y {
            (self.p0.y, self.p1.y, 1)
        } else {
            (self.p1.y, self.p0.y, -1)
        };
        if q.y < lo || q.y >= hi || q.x > self.max.x {
            return 0;
        }
        if q.x < self.min.x {
            return dir;
        }
        // y(s) = a s² + b s + p0.y, monotone on [0, 1]: its one root there.
        let a = self.p0.y - 2.0 * self.c.y + self.p1.y;
        let b = 2.0 * (self.c.y - self.p0.y);
        let s = monotone_root(a, b, self.p0.y - q.y).clamp(0.0, 1.0);
        if self.at(s).x > q.x {
            dir
        } else {
            0
        }
    }
}

/// The root in [0, 1] of a s² + b s + c for a quadratic that is monotone there (found with the
/// cancellation-free form of the quadratic formula).
fn monotone_root(a: f64, b: f64, c: f64) -> f64 {
    if a.abs() <= 1e-12 * b.abs() {
        return if b == 0.0 { 0.0 } else { -c / b };
    }
    let disc = (b * b - 4.0 * a * c).max(0.0).sqrt();
    let q = -0.5 * (b + disc.copysign(b));
    let r1 = q / a;
    let r2 = if q != 0.0 { c / q } else { r1 };
    // The one inside [0, 1], allowing for rounding at the ends.
    let inside = |r: f64| (-1e-9..=1.0 + 1e-9).contains(&r);
    if inside(r1) || !inside(r2) && (r1 - 0.5).abs() < (r2 - 0.5).abs() {
        r1
    } else {
        r2
    }
}

/// A glyph's outline in em units, in the font's own coordinates (before placing).
#[derive(Clone, Debug, Default)]
pub struct Glyph {
    pub id: u16,
    pub advance: f64,
    /// hmtx left side bearing. POV-Ray puts a glyph's left edge at the pen position plus this,
    /// whatever the outline's own xMin (they differ in povlogo.ttf's missing-glyph box).
    pub lsb: f64,
    pub pieces: Vec<Piece>,
    /// Bounds of the outline's points; `None` for a glyph with no outline (a space).
    pub bounds: Option<(DVec2, DVec2)>,
    /// The filled side of the contours: on the right of the direction of travel (TrueType's
    /// clockwise outer contours) or on the left (PostScript's convention).
    pub fill_right: bool,
    /// Which pieces each height band meets: `contains` and the side-wall search ask only those.
    pub bands: Bands,
}

impl Glyph {
    /// A glyph of these outline pieces (finite), with its bounds and band index.
    pub fn new(id: u16, advance: f64, lsb: f64, pieces: Vec<Piece>, fill_right: bool) -> Glyph {
        let bounds = pieces
            .iter()
            .map(|p| (p.min, p.max))
            .reduce(|a, b| (a.0.min(b.0), a.1.max(b.1)));
        let bands = bounds.map_or_else(Bands::default, |(lo, hi)| Bands::new(&pieces, lo.y, hi.y));
        Glyph {
            id,
            advance,
            lsb,
            pieces,
            bounds,
            fill_right,
            bands,
        }
    }

    /// Non-zero winding, as TrueType fills. Only pieces whose height range holds `q.y` can
    /// wind around it: the band's pieces (the sum is of integers, so their order is free).
    pub fn contains(&self, q: DVec2) -> bool {
        let Some((min, max)) = self.bounds else {
            return false;
        };
        if q.cmplt(min).any() || q.cmpgt(max).any() {
            return false;
        }
        let mut winding = 0;
        self.bands.each_in(self.pieces.len(), q.y, q.y, |i| {
            winding += self.pieces[i].winding(q)
        });
        winding != 0
    }

    /// Outward normal of the side wall at parameter `s` of piece `i`.
    pub fn wall_normal(&self, i: usize, s: f64) -> DVec2 {
        let Some(p) = self.pieces.get(i) else {
            return DVec2::X;
        };
        let t = p.tangent(s);
        if self.fill_right {
            DVec2::new(-t.y, t.x)
        } else {
            DVec2::new(t.y, -t.x)
        }
    }
}

/// Collects ttf-parser's outline calls as y-monotone quadratic pieces.
struct Collector {
    scale: f64,
    pieces: Vec<Piece>,
    start: DVec2,
    at: DVec2,
    open: bool,
    /// Twice the signed area of the control polygons, for the fill side.
    area2: f64,
}

impl Collector {
    fn pt(&self, x: f32, y: f32) -> DVec2 {
        DVec2::new(x as f64, y as f64) * self.scale
    }

    fn quad(&mut self, c: DVec2, p1: DVec2) {
        let p0 = self.at;
        self.area2 += p0.perp_dot(c) + c.perp_dot(p1);
        self.at = p1;
        if p0 == p1 && c == p0 {
            return;
        }
        // Split at the y extremum so each piece crosses a horizontal line at most once.
        let den = p0.y - 2.0 * c.y + p1.y;
        if den != 0.0 {
            let s = (p0.y - c.y) / den;
            if s > 0.0 && s < 1.0 {
                let c0 = p0.lerp(c, s);
                let c1 = c.lerp(p1, s);
                let m = c0.lerp(c1, s);
                // The split point is the extremum: its control points share its y exactly.
                let (c0, c1) = (DVec2::new(c0.x, m.y), DVec2::new(c1.x, m.y));
                self.pieces.push(Piece::new(p0, c0, m));
                self.pieces.push(Piece::new(m, c1, p1));
                return;
            }
        }
        self.pieces.push(Piece::new(p0, c, p1));
    }

    fn line(&mut self, p1: DVec2) {
        let p0 = self.at;
        self.quad((p0 + p1) * 0.5, p1);
    }

    fn close_contour(&mut self) {
        if self.open && self.at != self.start {
            self.line(self.start);
        }
        self.open = false;
    }
}

impl OutlineBuilder for Collector {
    fn move_to(&mut self, x: f32, y: f32) {
        self.close_contour();
        self.start = self.pt(x, y);
        self.at = self.start;
        self.open = true;
    }
    fn line_to(&mut self, x: f32, y: f32) {
        let p = self.pt(x, y);
        self.line(p);
    }
    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (c, p) = (self.pt(x1, y1), self.pt(x, y));
        self.quad(c, p);
    }
    /// Cubic curves come from CFF-flavoured OpenType fonts; four quadratics per cubic, each
    /// matching the cubic's ends and mid-point tangents, are within a small fraction of the
    /// outline's size for glyph-sized curves.
    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let p0 = self.at;
        let (c1, c2, p3) = (self.pt(x1, y1), self.pt(x2, y2), self.pt(x, y));
        let cubic = |s: f64| {
            let r = 1.0 - s;
            p0 * (r * r * r) + c1 * (3.0 * r * r * s) + c2 * (3.0 * r * s * s) + p3 * (s * s * s)
        };
        let deriv = |s: f64| {
            let r = 1.0 - s;
            (c1 - p0) * (3.0 * r * r) + (c2 - c1) * (6.0 * r * s) + (p3 - c2) * (3.0 * s * s)
        };
        const N: usize = 4;
        for k in 0..N {
            let (s0, s1) = (k as f64 / N as f64, (k + 1) as f64 / N as f64);
            let (a, b) = (cubic(s0), cubic(s1));
            let (da, db) = (deriv(s0) * (s1 - s0), deriv(s1) * (s1 - s0));
            // Where the end tangents meet; the midpoint of the two tangent estimates when
            // they are parallel.
            let den = da.perp_dot(db);
            let c = if den.abs() > 1e-18 {
                a + da * ((b - a).perp_dot(db) / den)
            } else {
                (a + da / 3.0 + b - db / 3.0) * 0.5
            };
            self.quad(c, b);
        }
    }
    fn close(&mut self) {
        self.close_contour();
    }
}

/// A loaded font file. ttf-parser's `Face` borrows the bytes, so the bytes are kept and the
/// face re-read (a table directory walk) for each layout rather than stored.
pub struct Font {
    pub path: PathBuf,
    data: Vec<u8>,
    scale: f64,
    glyphs: Mutex<HashMap<u16, Arc<Glyph>>>,
    /// Format 0 kerning pairs, in font units. Read into a map because the fonts POV-Ray ships
    /// (timrom, cyrvetic) list their pairs unsorted, where ttf-parser's binary search misses
    /// many that POV-Ray applies (timrom "WAVE" would be 0.137 too wide).
    pairs: HashMap<(u16, u16), i16>,
}

impl std::fmt::Debug for Font {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Font").field("path", &self.path).finish()
    }
}

/// A glyph placed in the text's coordinates: outline point p lands at `p + origin`.
#[derive(Clone, Debug)]
pub struct PlacedGlyph {
    pub glyph: Arc<Glyph>,
    pub origin: DVec2,
}

/// Result of laying a string out: the glyphs, and the characters the font has no glyph for
/// (drawn as the font's missing-glyph shape, glyph 0, as POV-Ray does).
#[derive(Debug, Default)]
pub struct Layout {
    pub glyphs: Vec<PlacedGlyph>,
    pub missing: Vec<char>,
}

/// Fonts already read in this process, by path, with the file's size and modification time:
/// a scene with a hundred texts, or an animation's every frame, reads each font file once.
type FontCache = HashMap<PathBuf, (Option<(u64, Option<std::time::SystemTime>)>, Arc<Font>)>;

fn cache() -> &'static Mutex<FontCache> {
    static CACHE: OnceLock<Mutex<FontCache>> = OnceLock::new();
    CACHE.get_or_init(Default::default)
}

impl Font {
    /// Reads and checks a font file, or returns the one read before if the file is unchanged.
    pub fn load(path: &Path) -> Result<Arc<Font>, String> {
        let stamp = std::fs::metadata(path)
            .ok()
            .map(|m| (m.len(), m.modified().ok()));
        let mut c = cache().lock().unwrap_or_else(|e| e.into_inner());
        if let Some((s, f)) = c.get(path) {
            if *s == stamp && stamp.is_some() {
                return Ok(f.clone());
            }
        }
        let data = std::fs::read(path)
            .map_err(|e| format!("cannot read font file {}: {e}", path.display()))?;
        let font = Arc::new(Font::from_bytes(path, data)?);
        c.insert(path.to_path_buf(), (stamp, font.clone()));
        Ok(font)
    }

    /// A font from bytes already read (a collection's first font, as POV-Ray takes).
    pub fn from_bytes(path: &Path, data: Vec<u8>) -> Result<Font, String> {
        let face = Face::parse(&data, 0).map_err(|e| {
            format!(
                "{} is not a TrueType font lancer can read ({e})",
                path.display()
            )
        })?;
        let upem = face.units_per_em();
        if upem == 0 {
            return Err(format!("{}: the font has 0 units per em", path.display()));
        }
        let mut pairs = HashMap::new();
        for st in face.tables().kern.into_iter().flat_map(|k| k.subtables) {
            if let (true, false, ttf_parser::kern::Format::Format0(f0)) =
                (st.horizontal, st.has_cross_stream, &st.format)
            {
                for p in f0.pairs {
                    pairs.entry((p.left().0, p.right().0)).or_insert(p.value);
                }
            }
        }
        Ok(Font {
            path: path.to_path_buf(),
            scale: 1.0 / upem as f64,
            data,
            glyphs: Mutex::new(HashMap::new()),
            pairs,
        })
    }

    fn face(&self) -> Face<'_> {
        // Parsed once successfully in `from_bytes`; the bytes have not changed since.
        Face::parse(&self.data, 0).expect("font parsed when loaded")
    }

    /// The glyph for a character: a Unicode cmap, else a symbol cmap (which maps the
    /// character codes to U+F000 + code, as povlogo.ttf's does), else the Macintosh table for
    /// ASCII; 0, the missing-glyph shape, when none has it.
    fn glyph_id(face: &Face, ch: char) -> Option<GlyphId> {
        if let Some(g) = face.glyph_index(ch).filter(|g| g.0 != 0) {
            return Some(g);
        }
        let cmap = face.tables().cmap?;
        let code = ch as u32;
        let found =
            cmap.subtables
                .into_iter()
                .find_map(|st| match (st.platform_id, st.encoding_id) {
                    (PlatformId::Windows, 0) => st.glyph_index(code).or_else(|| {
                        (code < 0x100)
                            .then(|| st.glyph_index(0xF000 + code))
                            .flatten()
                    }),
                    (PlatformId::Macintosh, 0) if code < 0x80 => st.glyph_index(code),
                    _ => None,
                });
        found.filter(|g| g.0 != 0)
    }

    /// The outline and metrics of a glyph, read once.
    fn glyph(&self, face: &Face, id: GlyphId) -> Arc<Glyph> {
        let mut cache = self.glyphs.lock().unwrap_or_else(|e| e.into_inner());
        cache
            .entry(id.0)
            .or_insert_with(|| Arc::new(self.read_glyph(face, id)))
            .clone()
    }

    fn read_glyph(&self, face: &Face, id: GlyphId) -> Glyph {
        let mut c = Collector {
            scale: self.scale,
            pieces: Vec::new(),
            start: DVec2::ZERO,
            at: DVec2::ZERO,
            open: false,
            area2: 0.0,
        };
        // A glyph whose outline cannot be read is drawn as nothing, keeping its advance.
        if face.outline_glyph(id, &mut c).is_none() {
            c.pieces.clear();
        }
        c.close_contour();
        let pieces: Vec<Piece> = c
            .pieces
            .into_iter()
            .filter(|p| p.min.is_finite() && p.max.is_finite())
            .collect();
        Glyph::new(
            id.0,
            face.glyph_hor_advance(id).unwrap_or(0) as f64 * self.scale,
            face.glyph_hor_side_bearing(id).unwrap_or(0) as f64 * self.scale,
            pieces,
            c.area2 <= 0.0,
        )
    }

    /// Kerning between two glyphs from the `kern` table's plain horizontal subtables: the
    /// format 0 pairs read at load, then ttf-parser's lookup for the other formats.
    fn kerning(&self, face: &Face, left: GlyphId, right: GlyphId) -> f64 {
        if let Some(&k) = self.pairs.get(&(left.0, right.0)) {
            return k as f64 * self.scale;
        }
        let Some(kern) = face.tables().kern else {
            return 0.0;
        };
        kern.subtables
            .into_iter()
            .filter(|st| {
                st.horizontal
                    && !st.variable
                    && !st.has_cross_stream
                    && !st.has_state_machine
                    && !matches!(st.format, ttf_parser::kern::Format::Format0(_))
            })
            .find_map(|st| st.glyphs_kerning(left, right))
            .map_or(0.0, |k| k as f64 * self.scale)
    }

    /// Places the glyphs of `text` as POV-Ray 3.7 does (measured against its `min_extent` and
    /// `max_extent` for the four fonts it ships): the pen starts at the origin and moves by
    /// each glyph's advance, the kerning with the next glyph and `offset`'s x and y (its z is
    /// not used); each glyph's left edge (outline xMin) sits at pen + lsb, and the whole
    /// string is moved left by the first glyph's lsb, so the first glyph starts at x = 0.
    /// `ascii_only` (charset ascii, POV-Ray's default) draws the missing glyph for every
    /// character above 127.
    pub fn layout(&self, text: &str, offset: DVec2, ascii_only: bool) -> Layout {
        let face = self.face();
        let mut out = Layout::default();
        let mut pen = DVec2::ZERO;
        let mut first_lsb = None;
        let mut prev: Option<GlyphId> = None;
        for ch in text.chars() {
            let id = if ascii_only && !ch.is_ascii() {
                None
            } else {
                Font::glyph_id(&face, ch)
            };
            if id.is_none() {
                out.missing.push(ch);
            }
            let id = id.unwrap_or(GlyphId(0));
            if let Some(p) = prev {
                pen.x += self.kerning(&face, p, id);
            }
            let glyph = self.glyph(&face, id);
            let shift = *first_lsb.get_or_insert(glyph.lsb);
            let xmin = glyph.bounds.map_or(glyph.lsb, |b| b.0.x);
            out.glyphs.push(PlacedGlyph {
                origin: DVec2::new(pen.x + glyph.lsb - xmin - shift, pen.y),
                glyph: glyph.clone(),
            });
            pen += DVec2::new(glyph.advance, 0.0) + offset;
            prev = Some(id);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DIR: &str = "/usr/share/povray-3.7/include";

    fn font(name: &str) -> Option<Arc<Font>> {
        let p = Path::new(DIR).join(name);
        if !p.exists() {
            eprintln!(
                "skipped: {} is not installed (povray-includes)",
                p.display()
            );
            return None;
        }
        Some(Font::load(&p).unwrap())
    }

    /// The string's extent along x, as POV-Ray's `max_extent` reports it.
    fn width(f: &Font, s: &str, off: f64) -> f64 {
        f.layout(s, DVec2::splat(off), true)
            .glyphs
            .iter()
            .filter_map(|g| g.glyph.bounds.map(|b| b.1.x + g.origin.x))
            .fold(0.0, f64::max)
    }

    #[test]
    fn widths_match_povray_max_extent() {
        // max_extent(text { ttf F S 1, 0 }).x from povray 3.7.
        let cases: &[(&str, &str, f64, f64)] = &[
            ("timrom.ttf", "H", 0.0, 0.711),
            ("timrom.ttf", "HH", 0.0, 1.462),
            ("timrom.ttf", "AV", 0.0, 1.278),
            ("timrom.ttf", "A V", 0.0, 1.719),
            ("timrom.ttf", "To", 0.0, 1.012),
            ("timrom.ttf", "i", 0.0, 0.233),
            ("timrom.ttf", "HH", 0.1, 1.562),
            ("timrom.ttf", "HH", -0.1, 1.362),
            ("timrom.ttf", " H", 0.0, 0.985),
            ("timrom.ttf", "jH", 0.0, 1.072),
            ("timrom.ttf", "AVAV", 0.0, 2.415),
            ("timrom.ttf", "WAVE", 0.0, 2.703),
            ("timrom.ttf", "Hello", 0.0, 2.221),
            ("cyrvetic.ttf", "H", 0.0, 0.561),
            ("cyrvetic.ttf", "AV", 0.0, 1.188),
            ("cyrvetic.ttf", "Hello", 0.0, 2.158),
            ("crystal.ttf", "H", 0.0, 0.337908),
            ("crystal.ttf", "AV", 0.0, 0.92092),
            ("crystal.ttf", "Hello", 0.0, 2.44972),
            ("povlogo.ttf", "P", 0.0, 0.669939),
            ("povlogo.ttf", "PV", 0.0, 1.373064),
            ("povlogo.ttf", "AP", 0.0, 1.67189),
            ("povlogo.ttf", " P", 0.0, 4.67189),
            ("povlogo.ttf", "P P", 0.0, 5.37502),
        ];
        for &(name, s, off, want) in cases {
            let Some(f) = font(name) else { return };
            let got = width(&f, s, off);
            assert!((got - want).abs() < 6e-5, "{name} {s:?}: {got} vs {want}");
        }
    }

    #[test]
    fn missing_glyphs_and_charsets() {
        let Some(f) = font("timrom.ttf") else { return };
        // é is not in timrom: the missing glyph (0.466 wide) with its advance, as POV-Ray.
        let l = f.layout("HéH", DVec2::ZERO, false);
        assert_eq!(l.missing, vec!['é']);
        assert_eq!(l.glyphs[1].glyph.id, 0);
        assert!((width(&f, "HéH", 0.0) - 2.008).abs() < 6e-5);
        // ™ is: drawn with utf8, missing with ascii.
        assert_ne!(f.layout("™", DVec2::ZERO, false).glyphs[0].glyph.id, 0);
        assert_eq!(f.layout("™", DVec2::ZERO, true).glyphs[0].glyph.id, 0);
        assert!(f.layout("", DVec2::ZERO, true).glyphs.is_empty());
    }

    #[test]
    fn winding_fills_glyph_and_leaves_counter() {
        let Some(f) = font("timrom.ttf") else { return };
        let o = &f.layout("O", DVec2::ZERO, true).glyphs[0].glyph;
        let (min, max) = o.bounds.unwrap();
        let mid = (min + max) * 0.5;
        assert!(!o.contains(mid), "the counter of O is empty");
        assert!(
            o.contains(DVec2::new(min.x + 0.02, mid.y)),
            "the left stroke"
        );
        assert!(!o.contains(DVec2::new(min.x - 0.01, mid.y)));
        for g in ["H", "o", "e", "g"] {
            let g = &f.layout(g, DVec2::ZERO, true).glyphs[0].glyph;
            assert!(g.fill_right, "TrueType outer contours are clockwise");
        }
    }

    #[test]
    fn fonts_and_glyphs_are_read_once() {
        let Some(a) = font("timrom.ttf") else { return };
        let b = font("timrom.ttf").unwrap();
        assert!(Arc::ptr_eq(&a, &b), "the second load is the cached font");
        let (x, y) = (
            a.layout("HH", DVec2::ZERO, true),
            b.layout("H", DVec2::ZERO, true),
        );
        assert!(Arc::ptr_eq(&x.glyphs[0].glyph, &x.glyphs[1].glyph));
        assert!(Arc::ptr_eq(&x.glyphs[0].glyph, &y.glyphs[0].glyph));
    }

    #[test]
    fn bad_font_bytes_are_an_error() {
        assert!(Font::from_bytes(Path::new("x.ttf"), b"not a font".to_vec()).is_err());
        assert!(Font::from_bytes(Path::new("x.ttf"), Vec::new()).is_err());
        assert!(Font::load(Path::new("/nonexistent/font.ttf")).is_err());
    }

    #[test]
    fn monotone_pieces_and_roots() {
        let mut c = Collector {
            scale: 1.0,
            pieces: Vec::new(),
            start: DVec2::ZERO,
            at: DVec2::ZERO,
            open: true,
            area2: 0.0,
        };
        c.quad(DVec2::new(1.0, 2.0), DVec2::new(2.0, 0.0));
        assert_eq!(c.pieces.len(), 2);
        for p in &c.pieces {
            assert!(p.c.y == p.p0.y.max(p.p1.y), "split at the top");
        }
        assert!((monotone_root(0.0, 2.0, -1.0) - 0.5).abs() < 1e-15);
        assert!((monotone_root(1.0, 0.0, -0.25) - 0.5).abs() < 1e-15);
    }
}
