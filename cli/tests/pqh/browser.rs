//! The HTML pages in a real headless browser (Debian's `chromium`, installed by `.ci/run`): they
//! load without script errors, draw something, and moving the step slider (through the page's
//! `#step=` fragment, which drives the slider) or the viewpoint changes the picture.
//!
//! They need Chromium, so they are `#[ignore]`d: the README's test command lists them as skipped,
//! and CI (which installs Chromium) runs them with `--run-ignored all`, where a missing browser is
//! a failure. `PQHULL_CHROMIUM` names another binary. `PQHULL_UPDATE_SCREENSHOTS=1`
//! rewrites `docs/images/trace-3d.png` from the 3-D comparison test.

use pqhull::hull::Event;
use pqhull::rbox::{Family, generate};
use pqhull::viz::html;
use pqhull::viz::scene::{Color, Panel, Scene, scene_page};
use pqhull::{ClosestToOrigin, Hull};
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

const WINDOW: (u32, u32) = (1000, 700);

fn chromium() -> Option<PathBuf> {
    if let Some(path) = std::env::var_os("PQHULL_CHROMIUM") {
        return Some(PathBuf::from(path));
    }
    [
        "/usr/bin/chromium",
        "/usr/bin/chromium-browser",
        "/usr/bin/google-chrome",
    ]
    .iter()
    .map(PathBuf::from)
    .find(|p| p.exists())
}

/// The browser; a test asked to run without one fails (it is only run on request).
fn browser() -> Option<PathBuf> {
    match chromium() {
        Some(path) => Some(path),
        None => panic!(
            "chromium not found (/usr/bin/chromium; or set PQHULL_CHROMIUM): install it with \
             `apt-get install chromium` (.ci/run does)"
        ),
    }
}

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("browser-tests");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir.join(name)
}

fn write_page(name: &str, page: &str) -> PathBuf {
    let path = scratch(name);
    std::fs::write(&path, page).expect("write page");
    path
}

fn url(page: &Path, fragment: &str) -> String {
    format!("file://{}#{fragment}", page.display())
}

/// Runs chromium headless on `url` with `extra` arguments, in a fresh profile, and returns its
/// standard output. Fails the test after 60 s.
fn chromium_run(exe: &Path, extra: &[String], url: &str) -> String {
    static RUN: AtomicUsize = AtomicUsize::new(0);
    let profile = scratch(&format!(
        "profile-{}-{}",
        std::process::id(),
        RUN.fetch_add(1, Ordering::Relaxed)
    ));
    let _ = std::fs::remove_dir_all(&profile);
    let mut child = Command::new(exe)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
            "--force-device-scale-factor=1",
            &format!("--window-size={},{}", WINDOW.0, WINDOW.1),
            &format!("--user-data-dir={}", profile.display()),
        ])
        .args(extra)
        .arg(url)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("start chromium");
    let started = Instant::now();
    let mut stdout = child.stdout.take().expect("stdout");
    let reader = std::thread::spawn(move || {
        let mut text = String::new();
        std::io::Read::read_to_string(&mut stdout, &mut text).map(|_| text)
    });
    loop {
        if child.try_wait().expect("wait for chromium").is_some() {
            break;
        }
        if started.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("chromium did not finish within 60 s on {url}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let _ = std::fs::remove_dir_all(&profile);
    reader.join().expect("reader").expect("chromium's output")
}

/// What the page reported about itself after its scripts ran.
struct PageState {
    errors: String,
    ready: bool,
    steps: String,
    /// The first canvas: left, top, width, height (CSS pixels = screenshot pixels here).
    canvas: [u32; 4],
    dom: String,
}

fn html_attribute(dom: &str, name: &str) -> Option<String> {
    let tag = &dom[dom.find("<html")?..];
    let tag = &tag[..tag.find('>')?];
    let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    let end = start + tag[start..].find('"')?;
    Some(tag[start..end].to_string())
}

fn load(exe: &Path, url: &str) -> PageState {
    let dom = chromium_run(exe, &["--dump-dom".to_string()], url);
    let canvas: Vec<u32> = html_attribute(&dom, "data-canvas")
        .unwrap_or_default()
        .split(',')
        .filter_map(|x| x.parse().ok())
        .collect();
    PageState {
        errors: html_attribute(&dom, "data-errors").expect("data-errors attribute"),
        ready: html_attribute(&dom, "data-ready").as_deref() == Some("1"),
        steps: html_attribute(&dom, "data-steps").unwrap_or_default(),
        canvas: canvas.try_into().unwrap_or([0; 4]),
        dom,
    }
}

fn assert_loaded(state: &PageState, what: &str) {
    assert_eq!(state.errors, "", "{what}: script errors");
    assert!(state.ready, "{what}: the viewer did not finish");
    assert!(
        state.canvas[2] >= 200 && state.canvas[3] >= 200,
        "{what}: canvas {:?}",
        state.canvas
    );
}

/// An RGBA screenshot: width, height, pixels.
struct Shot {
    width: usize,
    pixels: Vec<[u8; 4]>,
}

fn screenshot(exe: &Path, url: &str, file: &Path) -> Shot {
    let _ = std::fs::remove_file(file);
    chromium_run(exe, &[format!("--screenshot={}", file.display())], url);
    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(file).expect("chromium wrote no screenshot"),
    ));
    let mut reader = decoder.read_info().expect("a PNG");
    let mut buffer = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut buffer).expect("PNG frame");
    let channels = info.color_type.samples();
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    let pixels = buffer[..info.buffer_size()]
        .chunks_exact(channels)
        .map(|c| match channels {
            4 => [c[0], c[1], c[2], c[3]],
            3 => [c[0], c[1], c[2], 255],
            _ => [c[0], c[0], c[0], 255],
        })
        .collect();
    Shot {
        width: info.width as usize,
        pixels,
    }
}

impl Shot {
    /// The pixels inside `rect` (left, top, width, height), shrunk by 2 px for the border.
    fn region(&self, rect: [u32; 4]) -> Vec<[u8; 4]> {
        let [left, top, w, h] = rect.map(|x| x as usize);
        let mut out = Vec::new();
        for y in top + 2..top + h - 2 {
            for x in left + 2..(left + w - 2).min(self.width) {
                if let Some(p) = self.pixels.get(y * self.width + x) {
                    out.push(*p);
                }
            }
        }
        out
    }
}

/// Not blank: several distinct colours, and a fair share of pixels that are not background.
fn assert_drawn(region: &[[u8; 4]], what: &str) {
    let colours: HashSet<[u8; 4]> = region.iter().copied().collect();
    let inked = region.iter().filter(|p| p[..3] != [255, 255, 255]).count();
    assert!(
        colours.len() >= 12,
        "{what}: only {} colours: blank canvas?",
        colours.len()
    );
    assert!(
        inked * 50 >= region.len(),
        "{what}: only {inked} of {} pixels drawn",
        region.len()
    );
}

/// At least 0.5 % of the pixels differ.
fn assert_differ(a: &[[u8; 4]], b: &[[u8; 4]], what: &str) {
    assert_eq!(a.len(), b.len());
    let changed = a.iter().zip(b).filter(|(x, y)| x != y).count();
    assert!(
        changed * 200 >= a.len(),
        "{what}: only {changed} of {} pixels changed",
        a.len()
    );
}

#[test]
#[ignore = "needs headless Chromium; run with --run-ignored all (CI does)"]
fn three_d_trace_loads_draws_and_the_slider_changes_the_picture() {
    let Some(exe) = browser() else { return };
    let points = generate::<3>(&Family::SphereSurface, 80, 5);
    let (_, result, trace) =
        Hull::try_with_strategy_traced(&points, ClosestToOrigin::towards([0.1, -0.05, 0.15]))
            .unwrap();
    assert!(result.is_inside());
    let page = write_page(
        "trace-3d.html",
        &html::trace_page("3-D trace", &[&trace]).unwrap(),
    );
    // Step 1: the first choice; the last step: the stop, after every expansion.
    let first_choice = trace
        .events
        .iter()
        .position(|e| matches!(e, Event::Chose { .. }))
        .unwrap();
    let last = trace.events.len() - 1;
    let early = url(&page, &format!("step={first_choice}"));
    let state = load(&exe, &early);
    assert_loaded(&state, "3-D trace");
    assert_eq!(
        state.steps,
        first_choice.to_string(),
        "the slider follows #step="
    );
    assert!(
        state.dom.contains("chose facet #"),
        "the caption explains the step"
    );
    let a = screenshot(&exe, &early, &scratch("trace-3d-early.png")).region(state.canvas);
    let b = screenshot(
        &exe,
        &url(&page, &format!("step={last}")),
        &scratch("trace-3d-last.png"),
    )
    .region(state.canvas);
    assert_drawn(&a, "3-D trace, first choice");
    assert_drawn(&b, "3-D trace, last step");
    assert_differ(&a, &b, "moving the slider");
}

#[test]
#[ignore = "needs headless Chromium; run with --run-ignored all (CI does)"]
fn three_d_comparison_from_the_cli_loads_and_draws() {
    let Some(exe) = browser() else { return };
    let page = scratch("compare-3d.html");
    let o = Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args([
            "trace",
            "--family",
            "sphere",
            "--points",
            "70",
            "--dimension",
            "3",
            "--seed",
            "2",
            "--strategy",
            "closest",
            "--query",
            "0.12,-0.08,0.1",
            "--compare",
            "farthest",
            "--title",
            "pqh trace: ClosestToOrigin vs FarthestPoint, 70 points on a sphere",
            "--output",
        ])
        .arg(&page)
        .output()
        .expect("run pqh");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // Left: the partial hull at its stop; right: the full hull half built, at a choice.
    let fragment = "step=last,45&yaw=-0.5&pitch=0.35";
    let state = load(&exe, &url(&page, fragment));
    assert_loaded(&state, "3-D comparison");
    assert!(
        state.steps.ends_with(",45") && state.steps != "0,45",
        "{}",
        state.steps
    );
    assert!(state.dom.contains("(query inside)") && state.dom.contains("chose facet #"));
    let shot_file = scratch("compare-3d.png");
    let shot = screenshot(&exe, &url(&page, fragment), &shot_file);
    assert_drawn(&shot.region(state.canvas), "3-D comparison, left panel");
    let [left, top, w, h] = state.canvas;
    let right = [left + w + 14, top, w, h]; // the panels are laid out with a 14 px gap
    assert_drawn(&shot.region(right), "3-D comparison, right panel");
    if std::env::var("PQHULL_UPDATE_SCREENSHOTS").as_deref() == Ok("1") {
        let target =
            Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/..")).join("docs/images/trace-3d.png");
        std::fs::create_dir_all(target.parent().unwrap()).unwrap();
        std::fs::copy(&shot_file, &target).expect("update docs/images/trace-3d.png");
        eprintln!("updated {}", target.display());
    }
}

#[test]
#[ignore = "needs headless Chromium; run with --run-ignored all (CI does)"]
fn two_d_ows_page_from_the_cli_loads_and_draws() {
    let Some(exe) = browser() else { return };
    let page = scratch("ows-2d.html");
    let o = Command::new(env!("CARGO_BIN_EXE_pqh"))
        .args([
            "trace",
            "--family",
            "cube",
            "--points",
            "40",
            "--dimension",
            "2",
        ])
        .args(["--strategy", "ows", "--output"])
        .arg(&page)
        .output()
        .expect("run pqh");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let state = load(&exe, &url(&page, "step=0"));
    assert_loaded(&state, "2-D OWS");
    let a = screenshot(&exe, &url(&page, "step=0"), &scratch("ows-2d-0.png")).region(state.canvas);
    let b = screenshot(&exe, &url(&page, "step=last"), &scratch("ows-2d-last.png"))
        .region(state.canvas);
    assert_drawn(&a, "2-D OWS, initial simplex");
    assert_drawn(&b, "2-D OWS, stop");
    assert_differ(&a, &b, "2-D slider");
}

#[test]
#[ignore = "needs headless Chromium; run with --run-ignored all (CI does)"]
fn generic_scene_page_rotates_and_reports_errors() {
    let Some(exe) = browser() else { return };
    let mut scene = Scene::new("a box with a contact");
    let c = |i: usize| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64];
    for [a, b, d] in [
        [0, 1, 3],
        [0, 3, 2],
        [4, 5, 7],
        [4, 7, 6],
        [0, 1, 5],
        [0, 5, 4],
        [2, 3, 7],
        [2, 7, 6],
    ] {
        scene.triangle(
            [c(a), c(b), c(d)],
            Color::rgb(150, 180, 220).with_alpha(0.85),
        );
    }
    scene
        .point([1.0, 0.5, 0.5], Color::RED, 6.0)
        .segment([1.0, 0.5, 0.5], [0.7, 0.5, 0.5], Color::GREEN, 3.0)
        .label([1.0, 0.5, 0.5], "contact", Color::BLACK);
    let page = write_page(
        "scene.html",
        &scene_page("scene", &[Panel::new("box", vec![scene])]),
    );
    let state = load(&exe, &url(&page, "yaw=0.3"));
    assert_loaded(&state, "scene");
    let a = screenshot(&exe, &url(&page, "yaw=0.3"), &scratch("scene-a.png")).region(state.canvas);
    let b = screenshot(
        &exe,
        &url(&page, "yaw=1.4&pitch=-0.4"),
        &scratch("scene-b.png"),
    )
    .region(state.canvas);
    assert_drawn(&a, "scene");
    assert_differ(&a, &b, "rotating the view");

    // The error hook works: a page whose script throws says so (else "no errors" proves nothing).
    let broken = std::fs::read_to_string(&page)
        .unwrap()
        .replace("</body>", "<script>null.boom();</script></body>");
    let broken = write_page("broken.html", &broken);
    let state = load(&exe, &url(&broken, ""));
    assert!(
        state.errors.contains("null"),
        "error not recorded: {:?}",
        state.errors
    );
}

#[test]
#[ignore = "needs headless Chromium; run with --run-ignored all (CI does)"]
fn planned_grasps_page_loads_draws_both_panels_and_rotates() {
    let Some(exe) = browser() else { return };
    let page = scratch("plan.html");
    // `pqh demo`'s page on its defaults (the built-in spot.obj, 300 samples): the one README.md
    // shows; the full-hull check on one sample only.
    let o = Command::new(env!("CARGO_BIN_EXE_pqh"))
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .args(["demo", "--full-samples", "1", "--output"])
        .arg(&page)
        .output()
        .expect("run pqh");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let fragment = "yaw=0.6&pitch=0.3";
    let state = load(&exe, &url(&page, fragment));
    assert_loaded(&state, "planned grasps");
    assert!(state.dom.contains("best by Q1") && state.dom.contains("best by OWS"));
    assert!(state.dom.contains("The two grasps differ"), "{}", state.dom);
    let shot_file = scratch("plan.png");
    let shot = screenshot(&exe, &url(&page, fragment), &shot_file);
    let [left, top, w, h] = state.canvas;
    let right = [left + w + 14, top, w, h]; // the panels are laid out with a 14 px gap
    assert_drawn(&shot.region(state.canvas), "planned grasps, left panel");
    assert_drawn(&shot.region(right), "planned grasps, right panel");
    let turned = screenshot(
        &exe,
        &url(&page, "yaw=2.2&pitch=-0.4"),
        &scratch("plan-turned.png"),
    );
    assert_differ(
        &shot.region(state.canvas),
        &turned.region(state.canvas),
        "planned grasps, another viewpoint",
    );
    if std::env::var("PQHULL_UPDATE_SCREENSHOTS").as_deref() == Ok("1") {
        let target = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
            .join("docs/images/plan-grasp.png");
        std::fs::create_dir_all(target.parent().unwrap()).unwrap();
        std::fs::copy(&shot_file, &target).expect("update docs/images/plan-grasp.png");
        eprintln!("updated {}", target.display());
    }
}
