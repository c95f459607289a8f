//! HTML pages people look at: `lancer compare A B --html page.html` (one self-contained file,
//! the pictures inlined) and the conformance report (`lancer conformance --report PREFIX`
//! writes PREFIX.html beside the markdown, its pictures in PREFIX_files/): POV-Ray's picture,
//! lancer's and the heat map of their differences side by side, a table sortable by any
//! column (SSIM, times, missing keywords) with a few lines of script and no outside files.

use std::fmt::Write as _;

use base64::Engine as _;

use crate::compare::Comparison;
use crate::conformance::{Class, SceneResult};

/// Text made safe for HTML element content and attribute values.
pub fn escape(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&#39;"),
            c => o.push(c),
        }
    }
    o
}

/// PNG bytes as a `data:` URI, for a page that is one file.
pub fn png_data_uri(png: &[u8]) -> String {
    format!(
        "data:image/png;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(png)
    )
}

const STYLE: &str = "body{font-family:system-ui,sans-serif;margin:1.5em;color:#222}\
table{border-collapse:collapse}th,td{border:1px solid #ccc;padding:4px 8px;vertical-align:top}\
th{background:#eee;cursor:pointer;user-select:none}th.sorted-asc::after{content:' \\25B2'}\
th.sorted-desc::after{content:' \\25BC'}td.num{text-align:right;font-variant-numeric:tabular-nums}\
img{image-rendering:pixelated;border:1px solid #999;display:block}\
figure{display:inline-block;margin:0 12px 12px 0}figcaption{font-size:90%;color:#555}\
.good{background:#e3f6e3}.close{background:#fff6d6}.low{background:#fde2e2}\
.fail{background:#f0e0f6}.pics{white-space:nowrap}td.detail{min-width:9em;max-width:22em}";

/// Sorts the table `#results` by the clicked column: by `data-v` when the cell has one
/// (numbers), else by text; clicking again reverses. `page.html#sort=2` (`#sort=-2`) opens it
/// sorted by the third column, ascending (descending): links, and the headless-browser test.
const SORT_SCRIPT: &str = r#"<script>
document.querySelectorAll('#results th').forEach(function (th, col) {
  th.addEventListener('click', function () {
    var tbody = document.querySelector('#results tbody');
    var rows = Array.from(tbody.rows);
    var asc = !th.classList.contains('sorted-asc');
    document.querySelectorAll('#results th').forEach(function (h) {
      h.classList.remove('sorted-asc', 'sorted-desc');
    });
    th.classList.add(asc ? 'sorted-asc' : 'sorted-desc');
    function key(r) {
      var c = r.cells[col];
      var v = c.getAttribute('data-v');
      return v === null ? c.textContent.trim().toLowerCase() : v === '' ? null : parseFloat(v);
    }
    rows.sort(function (a, b) {
      var x = key(a), y = key(b);
      // Rows without a value (no SSIM: errors, POV-Ray failures) stay last either way.
      if (x === null || y === null) return (x === null) - (y === null);
      var r = x < y ? -1 : x > y ? 1 : 0;
      return asc ? r : -r;
    });
    rows.forEach(function (r) { tbody.appendChild(r); });
  });
});
(function () {
  var m = /^#sort=(-?)(\d+)$/.exec(location.hash);
  var th = m && document.querySelectorAll('#results th')[+m[2]];
  if (th) { th.click(); if (m[1]) th.click(); }
})();
</script>"#;

fn figure(src: &str, caption: &str, scale: u32, width: u32) -> String {
    format!(
        "<figure><img src=\"{}\" width=\"{}\" alt=\"{c}\"><figcaption>{c}</figcaption></figure>",
        escape(src),
        width * scale,
        c = escape(caption)
    )
}

/// The page for `lancer compare A B --html`: the two pictures and the heat map, and the numbers
/// `lancer compare` prints.
pub fn compare_page(
    a_name: &str,
    b_name: &str,
    a_png: &[u8],
    b_png: &[u8],
    heat_png: &[u8],
    c: &Comparison,
) -> String {
    // Small pictures are shown enlarged, pixel for pixel, three to a row on a wide screen.
    let scale = (400 / c.width.max(1)).clamp(1, 4);
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>lancer compare: \
         {a} vs {b}</title><style>{STYLE}</style></head><body>\n<h1>{a} vs {b}</h1>\n",
        a = escape(a_name),
        b = escape(b_name)
    );
    let _ = write!(
        h,
        "<table id=\"numbers\"><tr><th>SSIM</th><td class=\"num\">{:.6}</td></tr>\
         <tr><th>worst {t}x{t} tile</th><td class=\"num\">{:.6} at {},{}</td></tr>\
         <tr><th>PSNR</th><td class=\"num\">{}</td></tr><tr><th>size</th><td>{}x{}</td></tr>\
         </table>\n<div>",
        c.ssim,
        c.worst_tile.2,
        c.worst_tile.0,
        c.worst_tile.1,
        if c.psnr.is_infinite() {
            "inf".to_string()
        } else {
            format!("{:.2} dB", c.psnr)
        },
        c.width,
        c.height,
        t = crate::compare::TILE,
    );
    h.push_str(&figure(&png_data_uri(a_png), a_name, scale, c.width));
    h.push_str(&figure(&png_data_uri(b_png), b_name, scale, c.width));
    h.push_str(&figure(
        &png_data_uri(heat_png),
        "difference (dark: alike; red to white: less alike)",
        scale,
        c.width,
    ));
    h.push_str("</div>\n</body></html>\n");
    h
}

/// Where a conformance scene's pictures are, relative to the page; `None` when lancer made
/// none (errors, POV-Ray failures).
pub struct ScenePictures {
    pub povray: String,
    pub lancer: String,
    pub diff: String,
}

fn class_css(c: &Class) -> &'static str {
    match c {
        Class::Good => "good",
        Class::Close => "close",
        Class::Low => "low",
        _ => "fail",
    }
}

/// The conformance report as a page: a summary line, then one row per scene.
pub fn conformance_page(
    title: &str,
    summary: &str,
    results: &[SceneResult],
    pictures: &[Option<ScenePictures>],
    width: u32,
) -> String {
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{t}</title>\
         <style>{STYLE}</style></head><body>\n<h1>{t}</h1>\n<p>{}</p>\n<p>Click a column's \
         heading to sort by it.</p>\n<table id=\"results\"><thead><tr><th>#</th><th>scene</th>\
         <th>SSIM</th><th>result</th><th>POV-Ray | lancer | difference</th>\
         <th>missing keywords</th><th>lancer s</th><th>POV-Ray s</th></tr></thead><tbody>\n",
        escape(summary),
        t = escape(title),
    );
    for (i, r) in results.iter().enumerate() {
        let ssim = r.ssim.map_or((String::new(), "—".to_string()), |s| {
            (format!("{s:.6}"), format!("{s:.4}"))
        });
        let detail = match &r.class {
            Class::Error(m) | Class::Panic(m) | Class::PovFailed(m) => {
                format!("{}: {}", r.class.label(), m)
            }
            c => c.label().to_string(),
        };
        let pics = match pictures.get(i).and_then(Option::as_ref) {
            Some(p) => [
                (p.povray.as_str(), "POV-Ray"),
                (p.lancer.as_str(), "lancer"),
                (p.diff.as_str(), "difference"),
            ]
            .iter()
            .map(|(src, alt)| {
                format!(
                    "<img src=\"{}\" width=\"{width}\" alt=\"{alt}\" loading=\"lazy\" \
                     style=\"display:inline-block;margin-right:4px\">",
                    escape(src)
                )
            })
            .collect::<String>(),
            None => String::new(),
        };
        let _ = writeln!(
            h,
            "<tr class=\"{css}\"><td class=\"num\" data-v=\"{n}\">{n}</td><td>{name}</td>\
             <td class=\"num\" data-v=\"{sv}\">{st}</td><td class=\"detail\">{detail}</td><td class=\"pics\">\
             {pics}</td><td data-v=\"{nm}\">{missing}</td><td class=\"num\" data-v=\"{ls:.3}\">\
             {ls:.2}</td><td class=\"num\" data-v=\"{ps:.3}\">{ps:.2}</td></tr>",
            css = class_css(&r.class),
            n = i + 1,
            name = escape(&r.name),
            sv = ssim.0,
            st = ssim.1,
            detail = escape(&detail),
            nm = r.missing.len(),
            missing = escape(&r.missing.join(", ")),
            ls = r.lancer_seconds,
            ps = r.pov.seconds,
        );
    }
    h.push_str("</tbody></table>\n");
    h.push_str(SORT_SCRIPT);
    h.push_str("\n</body></html>\n");
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_markup() {
        assert_eq!(
            escape("<a href='x'>&\"</a>"),
            "&lt;a href=&#39;x&#39;&gt;&amp;&quot;&lt;/a&gt;"
        );
    }

    #[test]
    fn compare_page_inlines_three_pictures() {
        let p = crate::ssim::Picture::from_rgb8(16, 12, &[128; 16 * 12 * 3]);
        let c = crate::compare::compare(&p, &p).unwrap();
        let png = crate::compare::picture_png(&p).unwrap();
        let page = compare_page("a<b>.png", "b.png", &png, &png, &png, &c);
        assert_eq!(page.matches("data:image/png;base64,").count(), 3);
        assert!(page.contains("a&lt;b&gt;.png") && page.contains("1.000000"));
    }
}
