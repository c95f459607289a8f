//! The HTML reports (src/html_report.rs) opened in headless Chromium where it is installed
//! (Debian's `chromium`): `lancer compare --html` shows both pictures and the heat map (checked
//! on the screenshot's pixels), and the conformance page sorts by SSIM (checked on the DOM
//! after `#sort=-2`). Without Chromium only the files are checked.

use std::path::{Path, PathBuf};
use std::process::Command;

use lancer::conformance::cache::{PovResult, PovStatus};
use lancer::conformance::{Class, SceneResult};

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("lancer-html-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn chromium() -> Option<&'static str> {
    ["chromium", "chromium-browser"]
        .into_iter()
        .find(|c| Command::new(c).arg("--version").output().is_ok())
}

fn headless(browser: &str, dir: &Path, extra: &[&str], url: &str) -> Vec<u8> {
    let out = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
        ])
        .arg(format!("--user-data-dir={}", dir.join("profile").display()))
        .args(extra)
        .arg(url)
        .output()
        .expect("run chromium");
    out.stdout
}

fn write_png(path: &Path, w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 3]) {
    let mut img = image::RgbImage::new(w, h);
    for (x, y, p) in img.enumerate_pixels_mut() {
        *p = image::Rgb(f(x, y));
    }
    img.save(path).unwrap();
}

#[test]
fn compare_page_shows_both_pictures_and_the_heat_map() {
    let d = scratch("compare");
    // Blue everywhere; the second picture has a white square the heat map must show.
    write_png(&d.join("a.png"), 64, 48, |_, _| [20, 40, 200]);
    write_png(&d.join("b.png"), 64, 48, |x, y| {
        if (16..40).contains(&x) && (12..36).contains(&y) {
            [255, 255, 255]
        } else {
            [20, 40, 200]
        }
    });
    let page = d.join("page.html");
    let st = Command::new(env!("CARGO_BIN_EXE_lancer"))
        .current_dir(&d)
        .args(["compare", "a.png", "b.png", "--html", "page.html"])
        .output()
        .unwrap();
    assert!(st.status.success());
    let html = std::fs::read_to_string(&page).unwrap();
    assert_eq!(html.matches("data:image/png;base64,").count(), 3);
    let Some(browser) = chromium() else {
        eprintln!("no chromium: the page is not opened");
        return;
    };
    let shot = d.join("shot.png");
    headless(
        browser,
        &d,
        &[
            "--window-size=1200,700",
            &format!("--screenshot={}", shot.display()),
        ],
        &format!("file://{}", page.display()),
    );
    let img = image::open(&shot).expect("a screenshot").to_rgb8();
    let count = |f: &dyn Fn(&image::Rgb<u8>) -> bool| img.pixels().filter(|p| f(p)).count();
    // The pictures' blue, and the heat map's yellow-white to red where they differ.
    let blue = count(&|p| p[2] > 150 && p[0] < 60);
    let hot = count(&|p| p[0] > 200 && p[2] < 120);
    assert!(blue > 10_000, "{blue} blue pixels");
    assert!(hot > 1_000, "{hot} heat-map pixels");
}

fn result(name: &str, ssim: Option<f64>, class: Class) -> SceneResult {
    SceneResult {
        name: name.into(),
        class,
        ssim,
        lancer_seconds: 0.1,
        pov: PovResult {
            status: PovStatus::Ok,
            seconds: 1.0,
            work_seconds: 0.5,
            message: String::new(),
        },
        missing: vec!["quilted".into()],
    }
}

#[test]
fn conformance_page_sorts_by_ssim() {
    let d = scratch("conformance");
    let results = vec![
        result("b/mid.pov", Some(0.9), Class::Close),
        result("a/best.pov", Some(0.99), Class::Good),
        result("c/worst.pov", Some(0.1), Class::Low),
        result("d/error.pov", None, Class::Error("boom".into())),
    ];
    let pics: Vec<_> = results.iter().map(|_| None).collect();
    let html = lancer::html_report::conformance_page("t", "s", &results, &pics, 160);
    let page = d.join("conf.html");
    std::fs::write(&page, &html).unwrap();
    let Some(browser) = chromium() else {
        eprintln!("no chromium: the page is not opened");
        return;
    };
    let order = |hash: &str| -> Vec<String> {
        let dom = headless(
            browser,
            &d,
            &["--dump-dom"],
            &format!("file://{}{hash}", page.display()),
        );
        let dom = String::from_utf8_lossy(&dom).into_owned();
        dom.split("<td>")
            .skip(1)
            .filter_map(|c| c.split_once("</td>").map(|(t, _)| t.to_string()))
            .filter(|t| t.ends_with(".pov"))
            .collect()
    };
    assert_eq!(
        order("#sort=-2"),
        vec!["a/best.pov", "b/mid.pov", "c/worst.pov", "d/error.pov"]
    );
    assert_eq!(
        order("#sort=1"),
        vec!["a/best.pov", "b/mid.pov", "c/worst.pov", "d/error.pov"]
    );
    // Without an SSIM a row stays last, ascending too.
    assert_eq!(
        order("#sort=2"),
        vec!["c/worst.pov", "b/mid.pov", "a/best.pov", "d/error.pov"]
    );
}
