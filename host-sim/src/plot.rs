//! Line charts (plotters) written as SVG or PNG by the file's extension.
//!
//! Every figure of `crane-sim` goes through [`write_figure`]: one or more
//! panels stacked vertically, each with a title, axis labels with units, a
//! legend, and optionally horizontal reference lines and coloured bands
//! along x (the limiter's states). PNG text is drawn with the DejaVu Sans
//! font compiled into the binary, so no system font library is needed.

use anyhow::{anyhow, bail, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::element::DashedPathElement;
use plotters::style::register_font;
use std::path::Path;
use std::sync::OnceLock;

/// Width of every figure (pixels).
pub const WIDTH: u32 = 1000;
/// Height of one panel (pixels).
pub const PANEL_HEIGHT: u32 = 400;

/// Colours of the series, in order, when a series does not set its own.
pub const PALETTE: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(0, 0, 0),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
];

/// One curve of a chart.
pub struct Series<'a> {
    /// Legend label.
    pub label: &'a str,
    /// (x, y) points.
    pub points: &'a [(f64, f64)],
    /// Draw markers instead of a line.
    pub markers: bool,
    /// Colour; `None` takes the next of [`PALETTE`].
    pub color: Option<RGBColor>,
    /// Dashed line.
    pub dashed: bool,
}

impl<'a> Series<'a> {
    /// A solid line.
    pub fn line(label: &'a str, points: &'a [(f64, f64)]) -> Self {
        Self { label, points, markers: false, color: None, dashed: false }
    }

    /// Markers only.
    pub fn markers(label: &'a str, points: &'a [(f64, f64)]) -> Self {
        Self { label, points, markers: true, color: None, dashed: false }
    }

    /// With this colour.
    pub fn color(mut self, color: RGBColor) -> Self {
        self.color = Some(color);
        self
    }

    /// Dashed.
    pub fn dashed(mut self) -> Self {
        self.dashed = true;
        self
    }
}

/// A horizontal reference line across the whole panel.
pub struct HLine<'a> {
    /// Its y value.
    pub y: f64,
    /// Legend label.
    pub label: &'a str,
    /// Colour.
    pub color: RGBColor,
}

/// A coloured band over an x interval, full height (e.g. a limiter state).
pub struct Band {
    /// Start (x units).
    pub x0: f64,
    /// End (x units).
    pub x1: f64,
    /// Index into the panel's [`Panel::band_kinds`].
    pub kind: usize,
}

/// One panel: title, axis labels and what is drawn.
pub struct Panel<'a> {
    /// Caption.
    pub title: &'a str,
    /// x-axis label, with its unit.
    pub x_label: &'a str,
    /// y-axis label, with its unit.
    pub y_label: &'a str,
    /// Curves.
    pub series: Vec<Series<'a>>,
    /// Horizontal reference lines.
    pub hlines: Vec<HLine<'a>>,
    /// Coloured bands behind the curves.
    pub bands: Vec<Band>,
    /// Legend label and colour of each kind of band.
    pub band_kinds: Vec<(&'a str, RGBColor)>,
    /// Fixed y range; `None` fits the data.
    pub y_range: Option<(f64, f64)>,
    /// Where the legend goes; `None` picks the corner the curves leave freest.
    pub legend: Option<SeriesLabelPosition>,
}

impl<'a> Panel<'a> {
    /// A panel of curves, range fitted to the data.
    pub fn new(title: &'a str, x_label: &'a str, y_label: &'a str, series: Vec<Series<'a>>) -> Self {
        Self { title, x_label, y_label, series, hlines: Vec::new(), bands: Vec::new(), band_kinds: Vec::new(), y_range: None, legend: None }
    }
}

/// Registers the embedded font once (plotters' `ab_glyph` text needs it for
/// SVG layout and for PNG rendering alike).
fn ensure_font() -> Result<()> {
    static DONE: OnceLock<bool> = OnceLock::new();
    let ok = *DONE.get_or_init(|| {
        ["sans-serif", "serif", "monospace"].iter().all(|family| {
            register_font(family, FontStyle::Normal, dejavu::sans::regular()).is_ok()
                && register_font(family, FontStyle::Bold, dejavu::sans::bold()).is_ok()
        })
    });
    if ok {
        Ok(())
    } else {
        bail!("plot: the embedded font could not be loaded")
    }
}

fn bounds(panel: &Panel) -> (f64, f64, f64, f64) {
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    // x from every point with a finite x (a gap still spans time), y from
    // the finite values only.
    let mut take = |x: f64, y: f64| {
        if x.is_finite() {
            x0 = x0.min(x);
            x1 = x1.max(x);
        }
        if x.is_finite() && y.is_finite() {
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
    };
    for s in &panel.series {
        for &(x, y) in s.points {
            take(x, y);
        }
    }
    for b in &panel.bands {
        take(b.x0, f64::NAN);
        take(b.x1, f64::NAN);
    }
    if y0 > y1 {
        (y0, y1) = (0.0, 1.0);
    }
    if x0 > x1 {
        (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
    }
    for h in &panel.hlines {
        y0 = y0.min(h.y);
        y1 = y1.max(h.y);
    }
    if let Some((a, b)) = panel.y_range {
        (y0, y1) = (a, b);
    }
    let pad = |a: f64, b: f64, frac: f64| {
        if (b - a).abs() < 1e-12 * (1.0 + a.abs()) {
            let d = if a.abs() > 0.0 { 0.1 * a.abs() } else { 1.0 };
            (a - d, b + d)
        } else {
            (a - frac * (b - a), b + frac * (b - a))
        }
    };
    let (x0, x1) = pad(x0, x1, 0.0);
    let (y0, y1) = if panel.y_range.is_some() { (y0, y1) } else { pad(y0, y1, 0.05) };
    (x0, x1, y0, y1)
}

/// The corner of the plot with the fewest curve points under where the
/// legend would go (about a third of the width and of the height).
fn free_corner(panel: &Panel, (x0, x1, y0, y1): (f64, f64, f64, f64)) -> SeriesLabelPosition {
    use SeriesLabelPosition::{LowerLeft, LowerRight, MiddleRight, UpperLeft, UpperRight};
    let (w, h) = (x1 - x0, y1 - y0);
    let rows = 2 + panel.series.len() + panel.hlines.len() + panel.band_kinds.len();
    // The box's share of the height grows with its number of rows.
    let fh = (0.09 * rows as f64).min(0.6);
    let corners = [
        (UpperRight, (0.62, 1.0), (1.0 - fh, 1.0)),
        (LowerRight, (0.62, 1.0), (0.0, fh)),
        (UpperLeft, (0.0, 0.38), (1.0 - fh, 1.0)),
        (LowerLeft, (0.0, 0.38), (0.0, fh)),
        (MiddleRight, (0.62, 1.0), (0.5 - fh / 2.0, 0.5 + fh / 2.0)),
    ];
    let crowding = |(fx, fy): ((f64, f64), (f64, f64))| {
        let inside = |&(x, y): &(f64, f64)| {
            let (u, v) = ((x - x0) / w, (y - y0) / h);
            u >= fx.0 && u <= fx.1 && v >= fy.0 && v <= fy.1
        };
        let points: usize = panel.series.iter().map(|s| s.points.iter().filter(|p| inside(p)).count()).sum();
        let lines = panel.hlines.iter().filter(|l| inside(&(x0 + fx.0 * w, l.y))).count();
        points + 50 * lines
    };
    corners
        .into_iter()
        .min_by_key(|&(_, fx, fy)| crowding((fx, fy)))
        .map_or(UpperRight, |(pos, _, _)| pos)
}

/// A tick label without trailing zeros ("140", "2.5", "0.25").
fn tick(v: f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

/// Writes panels stacked vertically into one figure: PNG if `path` ends in
/// `.png`, SVG if it ends in `.svg` (any case); any other extension is an error.
pub fn write_figure(path: &Path, panels: &[Panel]) -> Result<()> {
    ensure_font()?;
    let size = (WIDTH, PANEL_HEIGHT * panels.len().max(1) as u32);
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("svg") => draw(SVGBackend::new(path, size).into_drawing_area(), panels),
        Some("png") => draw(BitMapBackend::new(path, size).into_drawing_area(), panels),
        _ => bail!("{}: a figure must end in .svg or .png", path.display()),
    }
    .map_err(|e| anyhow!("plot {}: {e}", path.display()))
}

/// Writes the same figure as `stem.svg` and `stem.png` in `dir`.
pub fn write_svg_and_png(dir: &Path, stem: &str, panels: &[Panel]) -> Result<()> {
    write_figure(&dir.join(format!("{stem}.svg")), panels)?;
    write_figure(&dir.join(format!("{stem}.png")), panels)
}

fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, panels: &[Panel]) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let e = |err: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("{err}");
    root.fill(&WHITE).map_err(e)?;
    let areas = root.split_evenly((panels.len().max(1), 1));
    for (panel, area) in panels.iter().zip(areas.iter()) {
        let (x0, x1, y0, y1) = bounds(panel);
        let mut chart = ChartBuilder::on(area)
            .caption(panel.title, ("sans-serif", 20))
            .margin(14)
            .x_label_area_size(48)
            .y_label_area_size(84)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(e)?;
        chart
            .configure_mesh()
            .x_desc(panel.x_label)
            .y_desc(panel.y_label)
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 15))
            .light_line_style(RGBColor(240, 240, 240))
            .max_light_lines(4)
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
            .draw()
            .map_err(e)?;
        for (kind, &(label, color)) in panel.band_kinds.iter().enumerate() {
            let fill = color.mix(0.22).filled();
            let rects: Vec<_> = panel
                .bands
                .iter()
                .filter(|b| b.kind == kind)
                .map(|b| Rectangle::new([(b.x0, y0), (b.x1, y1)], fill))
                .collect();
            if rects.is_empty() {
                continue;
            }
            chart
                .draw_series(rects)
                .map_err(e)?
                .label(label)
                .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], color.mix(0.4).filled()));
        }
        for h in &panel.hlines {
            let color = h.color;
            chart
                .draw_series(DashedLineSeries::new([(x0, h.y), (x1, h.y)], 8, 5, color.stroke_width(2)))
                .map_err(e)?
                .label(h.label)
                .legend(move |(x, y)| DashedPathElement::new(vec![(x, y), (x + 20, y)], 6, 3, color.stroke_width(2)));
        }
        let mut next = 0;
        for s in &panel.series {
            let color = s.color.unwrap_or_else(|| {
                let c = PALETTE[next % PALETTE.len()];
                next += 1;
                c
            });
            let legend_line = move |(x, y): (i32, i32)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2));
            if s.markers {
                let points = s.points.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite());
                chart
                    .draw_series(points.map(|(x, y)| Circle::new((x, y), 4, color.filled())))
                    .map_err(e)?
                    .label(s.label)
                    .legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled()));
                continue;
            }
            // A missing value (NaN) breaks the line rather than bridging the gap.
            let segments = s.points.split(|p| !(p.0.is_finite() && p.1.is_finite())).filter(|seg| !seg.is_empty());
            let mut labelled = false;
            for seg in segments {
                let drawn = if s.dashed {
                    chart.draw_series(DashedLineSeries::new(seg.iter().copied(), 6, 4, color.stroke_width(2))).map_err(e)?
                } else {
                    chart.draw_series(LineSeries::new(seg.iter().copied(), color.stroke_width(2))).map_err(e)?
                };
                if !labelled {
                    let drawn = drawn.label(s.label);
                    if s.dashed {
                        drawn.legend(move |(x, y)| DashedPathElement::new(vec![(x, y), (x + 20, y)], 6, 3, color.stroke_width(2)));
                    } else {
                        drawn.legend(legend_line);
                    }
                    labelled = true;
                }
            }
        }
        chart
            .configure_series_labels()
            .position(panel.legend.clone().unwrap_or_else(|| free_corner(panel, (x0, x1, y0, y1))))
            .label_font(("sans-serif", 14))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(e)?;
    }
    root.present().map_err(e)?;
    Ok(())
}

/// Refuses a figure path whose extension is neither `.svg` nor `.png`, before
/// any work is done.
pub fn check_figure_path(path: &Path) -> Result<()> {
    match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("svg" | "png") => Ok(()),
        _ => bail!("{}: a figure must end in .svg or .png", path.display()),
    }
}
