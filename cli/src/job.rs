//! What a command line asks trace to render: trace's own options over POV-Ray's switches
//! and INI options ([`PovSettings`]), resolved into the frames to render, each with its clock
//! and output file.

use crate::povray::PovSettings;
use std::path::{Path, PathBuf};
use trace::Clock;
use trace::film::{Format, Region};

/// A render's settings, the same for every frame.
#[derive(Debug)]
pub struct Job {
    pub scene: PathBuf,
    pub width: u32,
    pub height: u32,
    pub antialias: trace::Antialias,
    /// Method 3 draws area-light points from each pixel's sequence.
    pub sampled_lights: bool,
    /// Method 3 draws focal blur's lens points from each pixel's sequence.
    pub sampled_blur: bool,
    /// Radiosity's ground truth with this many paths a pixel.
    pub radiosity_reference: Option<u32>,
    /// Radiosity in POV-Ray's one-thread order.
    pub radiosity_povray_order: bool,
    pub threads: Option<u32>,
    pub include_paths: Vec<PathBuf>,
    pub declares: Vec<(String, f64)>,
    pub alpha: bool,
    pub bits: u8,
    pub region: Option<Region>,
    pub continue_trace: bool,
    pub aovs: Vec<trace::Aov>,
    pub frames: Vec<Frame>,
    pub warnings: Vec<String>,
}

/// One image to render.
#[derive(Debug)]
pub struct Frame {
    pub clock: Clock,
    pub output: PathBuf,
}

/// trace's own settings (from clap), each `None` where not given.
#[derive(Debug, Default)]
pub struct Own {
    pub scene: Option<PathBuf>,
    pub output: Option<PathBuf>,
    pub width: Option<u32>,
    pub height: Option<u32>,
    /// `None`: off; `Some(t)`: threshold t.
    pub aa: Option<Option<f64>>,
    pub aa_depth: Option<u32>,
    pub aa_method: Option<u32>,
    /// `--area-lights sampled`.
    pub sampled_lights: bool,
    /// `--focal-blur sampled`.
    pub sampled_blur: bool,
    /// `--radiosity-reference N`.
    pub radiosity_reference: Option<u32>,
    /// `--radiosity-povray-order`.
    pub radiosity_povray_order: bool,
    pub threads: Option<u32>,
    pub include_paths: Vec<PathBuf>,
    pub declares: Vec<(String, f64)>,
    pub region: Option<Region>,
    pub alpha: bool,
    pub bits: Option<u8>,
    pub clock: Option<f64>,
    pub frames: Option<(i64, i64)>,
    pub clocks: Option<(f64, f64)>,
    pub subset: Option<(i64, i64)>,
    pub cyclic: bool,
    pub continue_trace: bool,
    pub aovs: Vec<trace::Aov>,
}

/// Resolves the settings: trace's own first, then POV-Ray's, then the defaults (800 × 600,
/// anti-aliasing threshold 0.3 at depth 3, method 3 — method 1 when POV-Ray's jitter is
/// turned off, as a POV-Ray command line asking for its exact grid does — PNG).
pub fn resolve(own: Own, pov: PovSettings) -> Result<Job, String> {
    let mut scene = own
        .scene
        .clone()
        .or(pov.scene.clone())
        .ok_or("a scene file is required (trace SCENE, or +ISCENE)")?;
    // POV-Ray's `+Iscene` finds scene.pov.
    if !scene.exists() && scene.extension().is_none() {
        let pov_file = scene.with_extension("pov");
        if pov_file.exists() {
            scene = pov_file;
        }
    }
    let width = own.width.or(pov.width).unwrap_or(800);
    let height = own.height.or(pov.height).unwrap_or(600);
    for (name, v) in [("width", width), ("height", height)] {
        if !(1..=65536).contains(&v) {
            return Err(format!("the image {name} must be 1 to 65536, not {v}"));
        }
    }
    let threshold = match own.aa {
        Some(t) => t,
        None => match pov.antialias {
            Some(false) => None,
            _ => Some(pov.threshold.unwrap_or(0.3)),
        },
    };
    let depth = own.aa_depth.or(pov.aa_depth).unwrap_or(3);
    if !(1..=9).contains(&depth) {
        return Err(format!(
            "the anti-aliasing depth must be 1 to 9, not {depth}"
        ));
    }
    let mut warnings = pov.warnings.clone();
    let default_method = if pov.jitter == Some(false) { 1 } else { 3 };
    let method = own.aa_method.or(pov.aa_method).unwrap_or(default_method);
    if pov.jitter == Some(true) && method != 3 {
        warnings.push(format!(
            "Jitter: trace's method {method} samples POV-Ray's grid without jitter (method 3, \
             trace's own sampler, is the default)"
        ));
    }
    for (asked, option) in [
        (own.sampled_lights, "--area-lights sampled"),
        (own.sampled_blur, "--focal-blur sampled"),
    ] {
        if asked && (threshold.is_none() || method != 3) {
            return Err(format!(
                "{option} needs anti-aliasing method 3 (--aa-method 3)"
            ));
        }
    }
    let antialias = match (threshold, method) {
        (None, _) => trace::Antialias::Off,
        (Some(threshold), 1) => trace::Antialias::Adaptive { threshold, depth },
        (Some(threshold), 2) => trace::Antialias::Recursive { threshold, depth },
        (Some(threshold), 3) => trace::Antialias::Sampled { threshold, depth },
        (Some(_), m) => {
            return Err(format!(
                "anti-aliasing method {m}: trace has POV-Ray's methods 1 and 2 and its own method 3"
            ));
        }
    };
    if threshold.is_some_and(|t| !(t >= 0.0 && t.is_finite())) {
        return Err("the anti-aliasing threshold must be a number ≥ 0".into());
    }
    // The current folder after the scene's, as POV-Ray searches it.
    let include_paths = std::iter::once(PathBuf::from("."))
        .chain(own.include_paths.iter().cloned())
        .chain(pov.library_paths.iter().cloned())
        .chain(trace::standard_include_folder())
        .collect();
    // (POV-Ray: the first declaration of a name wins.)
    let mut declares: Vec<(String, f64)> = Vec::new();
    for (name, value) in own.declares.iter().chain(&pov.declares).cloned() {
        if !declares.iter().any(|(n, _)| *n == name) {
            declares.push((name, value));
        }
    }

    // The output: trace's -o picks the format by its extension; POV-Ray's +O gets the
    // extension of +F's type unless it has it; without either, the scene's name beside it.
    let pov_type = match pov.file_type.unwrap_or('N') {
        'E' => Format::Exr,
        'P' => Format::Ppm,
        _ => Format::Png,
    };
    let (output, format) = match own.output.clone() {
        Some(o) => {
            let f = Format::of(&o).ok_or_else(|| {
                format!(
                    "{}: unknown output format (use .png, .exr or .ppm)",
                    o.display()
                )
            })?;
            (o, f)
        }
        None => {
            let ext = pov_type.extension();
            let stem = scene
                .file_stem()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned();
            if pov.output.as_deref() == Some(Path::new("-")) {
                return Err(
                    "+O- (the image on standard output) is not supported: give a file name".into(),
                );
            }
            let o = match pov.output.clone() {
                Some(o) if o.as_os_str().to_string_lossy().ends_with('/') => {
                    o.join(format!("{stem}.{ext}"))
                }
                Some(o) => {
                    let name = o.to_string_lossy().trim_end_matches('.').to_string();
                    if name.ends_with(&format!(".{ext}")) {
                        PathBuf::from(name)
                    } else {
                        PathBuf::from(format!("{name}.{ext}"))
                    }
                }
                None => scene.with_file_name(format!("{stem}.{ext}")),
            };
            (o, pov_type)
        }
    };
    // POV-Ray writes its EXRs (+FE) in half floats whatever the bits per colour: so does trace
    // when POV-Ray's options name the file; trace's own `-o x.exr` writes 32-bit floats unless
    // `--bits 16`.
    let pov_exr = own.output.is_none() && format == Format::Exr;
    let bits = match own.bits.map(u32::from).or(pov.bits) {
        _ if pov_exr && own.bits.is_none() => 16,
        None | Some(8) => 8,
        Some(b) if (9..=16).contains(&b) => 16,
        Some(b) if (1..8).contains(&b) => 8,
        Some(b) => return Err(format!("{b} bits per colour: trace writes 8 or 16")),
    };
    let alpha = own.alpha || pov.alpha.unwrap_or(false);
    if alpha && format == Format::Ppm {
        warnings.push("a PPM file has no alpha channel: written without it".into());
    }

    let region = match own.region {
        Some(r) => Some(r),
        None => pov_region(&pov, width, height)?,
    };
    if let Some(r) = region {
        if r.x0 >= r.x1 || r.y0 >= r.y1 || r.x1 > width || r.y1 > height {
            return Err(format!(
                "the region {r} is not a rectangle inside the {width}x{height} image (X0,Y0,X1,Y1 in pixels, ends exclusive)"
            ));
        }
    }

    if !own.aovs.is_empty() && format != Format::Exr {
        return Err("AOV layers need an EXR output (-o NAME.exr or +FE)".into());
    }
    let frames = frames(&own, &pov, &output)?;
    Ok(Job {
        scene,
        width,
        height,
        antialias,
        sampled_lights: own.sampled_lights,
        sampled_blur: own.sampled_blur,
        radiosity_reference: own.radiosity_reference,
        radiosity_povray_order: own.radiosity_povray_order,
        threads: own.threads.or(pov.threads),
        include_paths,
        declares,
        alpha: alpha && format != Format::Ppm,
        bits,
        region: region.filter(|r| *r != Region::full(width, height)),
        continue_trace: own.continue_trace || pov.continue_trace.unwrap_or(false),
        aovs: own.aovs.clone(),
        frames,
        warnings,
    })
}

/// POV-Ray's `+SC +EC +SR +ER`: columns and rows from 1, inclusive, or fractions of the image
/// (a start below 1, an end up to 1).
fn pov_region(pov: &PovSettings, width: u32, height: u32) -> Result<Option<Region>, String> {
    let (sc, ec) = pov.columns;
    let (sr, er) = pov.rows;
    if [sc, ec, sr, er].iter().all(Option::is_none) {
        return Ok(None);
    }
    let start = |v: Option<f64>, size: u32| -> u32 {
        match v {
            None => 0,
            Some(v) if (0.0..1.0).contains(&v) => (size as f64 * v) as u32,
            Some(v) => (v as u32).saturating_sub(1),
        }
    };
    let end = |v: Option<f64>, size: u32| -> u32 {
        match v {
            None => size,
            Some(v) if (0.0..=1.0).contains(&v) => (size as f64 * v) as u32,
            Some(v) => (v as u32).min(size),
        }
    };
    let r = Region {
        x0: start(sc, width),
        y0: start(sr, height),
        x1: end(ec, width),
        y1: end(er, height),
    };
    Ok(Some(r))
}

/// The frames: one still, or POV-Ray's animation frames (`+KFI +KFF`, clock `+KI +KF`,
/// cyclic `+KC`, subset `+SF +EF`), each output named as POV-Ray names it: the frame number,
/// padded to the digits of the final frame, before the extension.
fn frames(own: &Own, pov: &PovSettings, output: &Path) -> Result<Vec<Frame>, String> {
    let (first, last) = match own.frames {
        Some(f) => f,
        None => (pov.frames.0.unwrap_or(1), pov.frames.1.unwrap_or(1)),
    };
    // (POV-Ray: frames 0..0 or 1..1 make a still; any other single frame is an animation of
    // one frame, whose clock POV-Ray makes NaN and trace the initial clock.)
    if first == last && (first == 0 || first == 1) {
        return Ok(vec![Frame {
            clock: Clock::still(own.clock.or(pov.clock)),
            output: output.to_path_buf(),
        }]);
    }
    if last < first {
        return Err(format!(
            "the final frame {last} comes before the initial frame {first}"
        ));
    }
    if last - first > 1_000_000 {
        return Err("more than a million frames".into());
    }
    let clocks = own
        .clocks
        .unwrap_or((pov.clocks.0.unwrap_or(0.0), pov.clocks.1.unwrap_or(1.0)));
    let cyclic = own.cyclic || pov.cyclic.unwrap_or(false);
    let subset = |v: Option<f64>, default: i64| -> i64 {
        match v {
            None => default,
            Some(v) if (0.0..=1.0).contains(&v) && v.fract() != 0.0 => {
                first + ((last - first) as f64 * v) as i64
            }
            Some(v) => v as i64,
        }
    };
    let (from, to) = match own.subset {
        Some(s) => s,
        None => (subset(pov.subset.0, first), subset(pov.subset.1, last)),
    };
    let (from, to) = (from.max(first), to.min(last));
    if from > to {
        return Err(format!("the subset of frames {from} to {to} is empty"));
    }
    let digits = (if cyclic { last + 1 } else { last }).to_string().len();
    let name = output.to_string_lossy();
    let (stem, ext) = match output.extension() {
        Some(e) => (
            name[..name.len() - e.len() - 1].to_string(),
            format!(".{}", e.to_string_lossy()),
        ),
        None => (name.to_string(), String::new()),
    };
    Ok((from..=to)
        .map(|n| Frame {
            clock: Clock::frame(n, (first, last), clocks, cyclic),
            output: PathBuf::from(format!("{stem}{n:0digits$}{ext}")),
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The anti-aliasing a command line resolves to, with the warnings.
    fn resolved(pov_args: &[&str], own: Own) -> Result<(trace::Antialias, Vec<String>), String> {
        let args = pov_args.iter().map(|s| s.to_string()).collect();
        let (_, pov) = crate::povray::split(args, |_| false)?;
        let own = Own {
            scene: Some(PathBuf::from("s.pov")),
            ..own
        };
        resolve(own, pov).map(|job| (job.antialias, job.warnings))
    }

    #[test]
    fn method_3_is_the_default_and_minus_j_asks_for_method_1() {
        let sampled = trace::Antialias::Sampled {
            threshold: 0.3,
            depth: 3,
        };
        let adaptive = trace::Antialias::Adaptive {
            threshold: 0.3,
            depth: 3,
        };
        assert_eq!(resolved(&[], Own::default()).unwrap().0, sampled);
        assert_eq!(resolved(&["+A0.3"], Own::default()).unwrap().0, sampled);
        assert_eq!(
            resolved(&["+J"], Own::default()).unwrap(),
            (sampled, vec![])
        );
        assert_eq!(resolved(&["-J"], Own::default()).unwrap().0, adaptive);
        assert_eq!(
            resolved(&["+A0.3", "+R3", "-J"], Own::default()).unwrap().0,
            adaptive
        );
        // An explicit method wins over -J; jitter asked of method 1 is warned about.
        let own3 = Own {
            aa_method: Some(3),
            ..Own::default()
        };
        assert_eq!(resolved(&["-J"], own3).unwrap().0, sampled);
        let (aa, warnings) = resolved(&["+AM1", "+J"], Own::default()).unwrap();
        assert_eq!(aa, adaptive);
        assert!(
            warnings.iter().any(|w| w.contains("Jitter")),
            "{warnings:?}"
        );
    }

    #[test]
    fn sampled_area_lights_need_method_3() {
        let own = |method| Own {
            aa_method: method,
            sampled_lights: true,
            ..Own::default()
        };
        assert!(resolved(&[], own(None)).is_ok());
        let e = resolved(&[], own(Some(1))).unwrap_err();
        assert!(e.contains("method 3"), "{e}");
        assert!(resolved(&["-A"], own(None)).is_err());
    }
}
