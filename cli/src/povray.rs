//! POV-Ray's command line beside trace's own: `+W320`-style switches, `Key=Value` options and
//! INI files (`render.ini`, `render.ini[Section]`), read in order into [`PovSettings`], the
//! layer below trace's own options (which win where both are given).

use std::path::{Path, PathBuf};

/// What POV-Ray's switches and INI options asked for (`None`: not given).
#[derive(Debug, Default)]
pub struct PovSettings {
    pub scene: Option<PathBuf>,
    pub output: Option<PathBuf>,
    pub width: Option<u32>,
    pub height: Option<u32>,
    pub antialias: Option<bool>,
    pub threshold: Option<f64>,
    pub aa_depth: Option<u32>,
    pub aa_method: Option<u32>,
    /// `Jitter` / `+J`: on or off, if given.
    pub jitter: Option<bool>,
    pub library_paths: Vec<PathBuf>,
    pub declares: Vec<(String, f64)>,
    /// `Start_Column`, `End_Column`, `Start_Row`, `End_Row` as given (pixels from 1, or
    /// fractions of the image).
    pub columns: (Option<f64>, Option<f64>),
    pub rows: (Option<f64>, Option<f64>),
    pub clock: Option<f64>,
    pub frames: (Option<i64>, Option<i64>),
    pub clocks: (Option<f64>, Option<f64>),
    pub subset: (Option<f64>, Option<f64>),
    pub cyclic: Option<bool>,
    pub alpha: Option<bool>,
    pub file_type: Option<char>,
    pub bits: Option<u32>,
    pub threads: Option<u32>,
    pub continue_trace: Option<bool>,
    /// Options accepted without effect, each with why (printed as warnings).
    pub warnings: Vec<String>,
}

/// How trace reads POV-Ray's options, for the documentation and the error messages: the
/// switch, its INI name, and what trace does with it.
pub const OPTIONS: &[(&str, &str, &str)] = &[
    ("+W", "Width", "image width"),
    ("+H", "Height", "image height"),
    (
        "+A[t] / -A",
        "Antialias, Antialias_Threshold",
        "anti-aliasing on (threshold t, default 0.3) or off",
    ),
    ("+R", "Antialias_Depth", "anti-aliasing depth"),
    (
        "+AM",
        "Sampling_Method",
        "anti-aliasing method 1, 2 or 3 (trace's own sampler)",
    ),
    (
        "+J / -J",
        "Jitter, Jitter_Amount",
        "off (`-J`) makes method 1 the default, for POV-Ray's exact grid; on, the default stays method 3 (trace's own sampler); methods 1 and 2 never jitter (warning)",
    ),
    ("+I", "Input_File_Name", "the scene"),
    (
        "+O",
        "Output_File_Name",
        "the output file (a folder if it ends in /)",
    ),
    ("+L", "Library_Path", "an include folder (repeatable)"),
    (
        "",
        "Declare=NAME=VALUE",
        "a float identifier declared before the scene",
    ),
    (
        "+SC +EC +SR +ER",
        "Start_Column, End_Column, Start_Row, End_Row",
        "render a region (pixels from 1, inclusive; or fractions 0-1)",
    ),
    ("+K", "Clock", "the clock of a still"),
    (
        "+KFI +KFF",
        "Initial_Frame, Final_Frame",
        "animation frames",
    ),
    (
        "+KI +KF",
        "Initial_Clock, Final_Clock",
        "the clock over the frames",
    ),
    ("+KC", "Cyclic_Animation", "cyclic animation"),
    (
        "+SF +EF",
        "Subset_Start_Frame, Subset_End_Frame",
        "render a subset of the frames",
    ),
    ("+UA", "Output_Alpha", "alpha channel"),
    (
        "+FN[8|16] +FE +FP[8|16]",
        "Output_File_Type, Bits_Per_Color",
        "PNG, EXR, PPM; other types refused",
    ),
    ("+WT", "Work_Threads", "worker threads"),
    ("+C", "Continue_Trace", "continue an interrupted render"),
    (
        "+D +V +P +X +GA +Q +BS +MB +MV",
        "Display, Verbose, Pause_When_Done, Test_Abort, *_Console, Quality, Render_Block_Size, Bounding, Version",
        "accepted without effect (Quality below 9 and Display on with a warning)",
    ),
];

/// Splits `args` (without the program name) into trace's own arguments, for clap, and
/// POV-Ray's, read into [`PovSettings`]. `takes_value` tells which of trace's long options
/// take the next argument as their value.
pub fn split(
    args: Vec<String>,
    takes_value: impl Fn(&str) -> bool,
) -> Result<(Vec<String>, PovSettings), String> {
    let mut own = Vec::new();
    let mut pov = PovSettings::default();
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        if let Some(long) = arg.strip_prefix("--") {
            let takes = !long.contains('=') && takes_value(long);
            own.push(arg);
            if takes {
                own.extend(args.next());
            }
        } else if matches!(arg.as_str(), "-o" | "-L") {
            own.push(arg);
            own.extend(args.next());
        } else if matches!(arg.as_str(), "-q" | "-h" | "-") {
            own.push(arg);
        } else if arg.len() > 1 && (arg.starts_with('+') || arg.starts_with('-')) {
            switch(&arg, &mut pov)?;
        } else if let Some((file, section)) = ini_file(&arg) {
            read_ini(Path::new(&file), section.as_deref(), &mut pov, 0)?;
        } else if let Some((key, value)) = assignment(&arg) {
            option(key, value, &mut pov).map_err(|e| format!("`{arg}`: {e}"))?;
        } else {
            own.push(arg);
        }
    }
    Ok((own, pov))
}

/// `file.ini` or `file.ini[Section]`.
fn ini_file(arg: &str) -> Option<(String, Option<String>)> {
    let (file, section) = match arg.strip_suffix(']').and_then(|a| a.rsplit_once('[')) {
        Some((file, section)) => (file, Some(section.to_string())),
        None => (arg, None),
    };
    let lower = file.to_ascii_lowercase();
    lower.ends_with(".ini").then(|| (file.to_string(), section))
}

/// `Key=Value` with a key of letters, digits and underscores.
fn assignment(arg: &str) -> Option<(&str, &str)> {
    let (key, value) = arg.split_once('=')?;
    let key = key.trim();
    let ok = !key.is_empty()
        && key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && key.starts_with(|c: char| c.is_ascii_alphabetic());
    ok.then_some((key, value.trim()))
}

/// Reads an INI file: `Key=Value` lines, switches, `;` and `#` comments; the lines before the
/// first `[Section]` label, and with a section named, the lines under each label of that name
/// (any case), as POV-Ray reads them.
fn read_ini(
    path: &Path,
    section: Option<&str>,
    pov: &mut PovSettings,
    depth: u32,
) -> Result<(), String> {
    if depth > 10 {
        return Err(format!(
            "{}: INI files include each other more than 10 deep",
            path.display()
        ));
    }
    let text = std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let text = String::from_utf8_lossy(&text);
    let mut active = true;
    for (n, line) in text.lines().enumerate() {
        let at = |e: String| format!("{}:{}: {e}", path.display(), n + 1);
        let line = match line.find([';', '#']) {
            Some(i) => &line[..i],
            None => line,
        }
        .trim();
        if line.is_empty() {
            continue;
        }
        if let Some(label) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
            active = section.is_some_and(|s| s.trim().eq_ignore_ascii_case(label.trim()));
            continue;
        }
        if !active {
            continue;
        }
        if let Some((key, value)) = assignment(line) {
            if key.eq_ignore_ascii_case("Include_Ini") {
                let value = unquote(value);
                let (file, section) = ini_file(value).unwrap_or((value.to_string(), None));
                let file = path.parent().unwrap_or(Path::new("")).join(file);
                read_ini(&file, section.as_deref(), pov, depth + 1).map_err(at)?;
            } else {
                option(key, value, pov).map_err(at)?;
            }
        } else {
            for word in line.split_whitespace() {
                if word.starts_with('+') || word.starts_with('-') {
                    switch(word, pov).map_err(at)?;
                } else if let Some((file, section)) = ini_file(word) {
                    read_ini(Path::new(&file), section.as_deref(), pov, depth + 1).map_err(at)?;
                } else {
                    return Err(at(format!("`{word}` is neither an option nor a switch")));
                }
            }
        }
    }
    Ok(())
}

fn unquote(v: &str) -> &str {
    let v = v.trim();
    v.strip_prefix('"')
        .and_then(|v| v.strip_suffix('"'))
        .unwrap_or(v)
}

/// POV-Ray's booleans: empty, or the start of on, true, yes or 1, is on; anything else off.
fn boolean(v: &str) -> Result<bool, String> {
    let v = v.trim().to_ascii_lowercase();
    Ok(v.is_empty()
        || ["on", "true", "yes", "1"]
            .iter()
            .any(|w| w.starts_with(&v) || v.starts_with(w) && *w == "on"))
}

fn number<T: std::str::FromStr>(v: &str) -> Result<T, String> {
    v.trim()
        .parse()
        .map_err(|_| format!("expected a number, found `{v}`"))
}

/// One INI option (`Width=320`), by POV-Ray's name (any case).
fn option(key: &str, value: &str, pov: &mut PovSettings) -> Result<(), String> {
    let key = key.to_ascii_lowercase();
    let v = unquote(value);
    match key.as_str() {
        "width" => pov.width = Some(number(v)?),
        "height" => pov.height = Some(number(v)?),
        "antialias" => pov.antialias = Some(boolean(v)?),
        "antialias_threshold" => pov.threshold = Some(number(v)?),
        "antialias_depth" => pov.aa_depth = Some(number(v)?),
        "sampling_method" => pov.aa_method = Some(number(v)?),
        "jitter" => pov.jitter = Some(boolean(v)?),
        "input_file_name" => pov.scene = Some(PathBuf::from(v)),
        "output_file_name" => pov.output = Some(PathBuf::from(v)),
        "library_path" => pov.library_paths.push(PathBuf::from(v)),
        "declare" => {
            let (name, value) = v
                .split_once('=')
                .ok_or_else(|| format!("expected Declare=NAME=VALUE, found `{v}`"))?;
            if !trace::is_identifier(name.trim()) {
                return Err(format!("`{name}` is not an identifier"));
            }
            pov.declares.push((name.trim().to_string(), number(value)?));
        }
        "start_column" => pov.columns.0 = Some(number(v)?),
        "end_column" => pov.columns.1 = Some(number(v)?),
        "start_row" => pov.rows.0 = Some(number(v)?),
        "end_row" => pov.rows.1 = Some(number(v)?),
        "clock" => pov.clock = Some(number(v)?),
        "initial_frame" => pov.frames.0 = Some(number(v)?),
        "final_frame" => pov.frames.1 = Some(number(v)?),
        "initial_clock" => pov.clocks.0 = Some(number(v)?),
        "final_clock" => pov.clocks.1 = Some(number(v)?),
        "subset_start_frame" => pov.subset.0 = Some(number(v)?),
        "subset_end_frame" => pov.subset.1 = Some(number(v)?),
        "cyclic_animation" => pov.cyclic = Some(boolean(v)?),
        "output_alpha" => pov.alpha = Some(boolean(v)?),
        "output_file_type" => {
            let t = v.chars().next().unwrap_or('N').to_ascii_uppercase();
            file_type(t)?;
            pov.file_type = Some(t);
        }
        "bits_per_color" | "bits_per_colour" => pov.bits = Some(number(v)?),
        "work_threads" => pov.threads = Some(number(v)?),
        "continue_trace" => pov.continue_trace = Some(boolean(v)?),
        "quality" => {
            if number::<f64>(v)? < 9.0 {
                pov.warnings.push(format!(
                    "Quality={v}: trace renders at full quality (POV-Ray's 9)"
                ));
            }
        }
        "display" => {
            if boolean(v)? {
                pov.warnings
                    .push("Display: trace shows no preview window".into());
            }
        }
        "output_to_file" => {
            if !boolean(v)? {
                return Err("trace always writes its image (Output_To_File=off refused)".into());
            }
        }
        "verbose"
        | "pause_when_done"
        | "test_abort"
        | "test_abort_count"
        | "all_console"
        | "debug_console"
        | "fatal_console"
        | "render_console"
        | "statistic_console"
        | "warning_console"
        | "all_file"
        | "debug_file"
        | "fatal_file"
        | "render_file"
        | "statistic_file"
        | "warning_file"
        | "render_block_size"
        | "render_block_step"
        | "render_pattern"
        | "bounding"
        | "bounding_threshold"
        | "bounding_method"
        | "light_buffer"
        | "vista_buffer"
        | "remove_bounds"
        | "split_unions"
        | "draw_vistas"
        | "preview_start_size"
        | "preview_end_size"
        | "version"
        | "display_gamma"
        | "antialias_gamma"
        | "max_image_buffer_memory"
        | "buffer_output"
        | "buffer_size"
        | "histogram_type"
        | "create_ini"
        | "field_render"
        | "odd_field"
        | "palette"
        | "dither"
        | "dither_method"
        | "file_gamma"
        | "pre_scene_command"
        | "pre_frame_command"
        | "post_scene_command"
        | "post_frame_command"
        | "user_abort_command"
        | "fatal_error_command"
        | "pre_scene_return"
        | "pre_frame_return"
        | "post_scene_return"
        | "post_frame_return"
        | "user_abort_return"
        | "fatal_error_return" => {}
        _ => return Err(format!("unknown POV-Ray option `{key}`")),
    }
    Ok(())
}

/// Checks an output file type letter (POV-Ray's `+F?`).
fn file_type(t: char) -> Result<(), String> {
    match t {
        'N' | 'E' | 'P' => Ok(()),
        _ => Err(format!(
            "output file type `{t}`: trace writes PNG (N), OpenEXR (E) and PPM (P)"
        )),
    }
}

/// POV-Ray's switches and the INI options they set, longest names first (`+KFI` before `+KF`
/// before `+K`): a switch with a value passes it on (`+W320` is `Width=320`); a flag passes
/// `+` as on and `-` as off (`+UA` is `Output_Alpha=on`).
const SWITCHES: &[(&str, &str, bool)] = &[
    ("KFI", "initial_frame", true),
    ("KFF", "final_frame", true),
    ("KC", "cyclic_animation", false),
    ("KI", "initial_clock", true),
    ("KF", "final_clock", true),
    ("K", "clock", true),
    ("AM", "sampling_method", true),
    ("AG", "antialias_gamma", true),
    ("SC", "start_column", true),
    ("SR", "start_row", true),
    ("SF", "subset_start_frame", true),
    ("SP", "preview_start_size", true),
    ("EC", "end_column", true),
    ("ER", "end_row", true),
    ("EF", "subset_end_frame", true),
    ("EP", "preview_end_size", true),
    ("UA", "output_alpha", false),
    ("UD", "draw_vistas", false),
    ("UL", "light_buffer", false),
    ("UR", "remove_bounds", false),
    ("UV", "vista_buffer", false),
    ("WT", "work_threads", true),
    ("W", "width", true),
    ("H", "height", true),
    ("R", "antialias_depth", true),
    ("J", "jitter", false),
    ("I", "input_file_name", true),
    ("O", "output_file_name", true),
    ("L", "library_path", true),
    ("C", "continue_trace", false),
    ("D", "display", false),
    ("V", "verbose", false),
    ("P", "pause_when_done", false),
    ("X", "test_abort", false),
    ("Q", "quality", true),
    ("BS", "render_block_size", true),
    ("MB", "bounding", false),
    ("MV", "version", true),
    ("GA", "all_console", false),
    ("GD", "debug_console", false),
    ("GF", "fatal_console", false),
    ("GR", "render_console", false),
    ("GS", "statistic_console", false),
    ("GW", "warning_console", false),
    ("GP", "all_console", false),
];

/// One switch (`+W320`, `-A`, `+KFI1`), case-insensitive, read as the INI option it stands for.
fn switch(arg: &str, pov: &mut PovSettings) -> Result<(), String> {
    let on = arg.starts_with('+');
    let body = &arg[1..];
    let upper = body.to_ascii_uppercase();
    let bad = |e: String| format!("`{arg}`: {e}");
    let flag = if on { "on" } else { "off" };
    // `+A[t]`, `-A[t]`: on or off, and the threshold if given; `+AM`, `+AG` come from the table.
    if upper.starts_with('A') && !upper.starts_with("AM") && !upper.starts_with("AG") {
        option("antialias", flag, pov).map_err(bad)?;
        return match &body[1..] {
            "" => Ok(()),
            t => option("antialias_threshold", t, pov).map_err(bad),
        };
    }
    // `+F[type][bits]`: the output type and its bits per colour.
    if let Some(rest) = upper.strip_prefix('F') {
        if !on && rest.is_empty() {
            return Err(format!("{arg}: trace always writes its image"));
        }
        if let Some(t) = rest.get(..1) {
            option("output_file_type", t, pov).map_err(bad)?;
            if rest.len() > 1 {
                option("bits_per_color", &rest[1..], pov).map_err(bad)?;
            }
        }
        return Ok(());
    }
    if upper.starts_with("GI") {
        return Err(format!("{arg}: trace does not write INI files"));
    }
    let Some(&(name, key, takes_value)) = SWITCHES.iter().find(|(n, ..)| upper.starts_with(n))
    else {
        let known: Vec<&str> = OPTIONS
            .iter()
            .map(|o| o.0)
            .filter(|s| !s.is_empty())
            .collect();
        return Err(format!(
            "unknown POV-Ray switch `{arg}` (trace reads {}; docs/command-line.md)",
            known.join(", ")
        ));
    };
    let value = &body[name.len()..];
    if !takes_value {
        return option(key, flag, pov).map_err(bad);
    }
    // (`+Q` without a value, and the other value switches accepted without effect, read nothing.)
    if value.is_empty()
        && matches!(
            key,
            "quality"
                | "render_block_size"
                | "version"
                | "preview_start_size"
                | "preview_end_size"
                | "antialias_gamma"
        )
    {
        return Ok(());
    }
    option(key, value, pov).map_err(bad)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pov(args: &[&str]) -> PovSettings {
        let args = args.iter().map(|s| s.to_string()).collect();
        split(args, |_| true).unwrap().1
    }

    #[test]
    fn switches_are_read_in_any_case_and_later_ones_win() {
        let p = pov(&[
            "+W320", "+h240", "-w640", "+A0.2", "-A", "+AM2", "+R4", "+KFI1", "+KFF10",
        ]);
        assert_eq!((p.width, p.height), (Some(640), Some(240)));
        assert_eq!((p.antialias, p.threshold), (Some(false), Some(0.2)));
        assert_eq!((p.aa_method, p.aa_depth), (Some(2), Some(4)));
        assert_eq!(p.frames, (Some(1), Some(10)));
    }

    #[test]
    fn trace_options_pass_through() {
        let args = [
            "scene.pov",
            "--width",
            "320",
            "-o",
            "a.png",
            "+H240",
            "Width=100",
            "-q",
        ];
        let (own, p) = split(args.iter().map(|s| s.to_string()).collect(), |l| {
            l == "width"
        })
        .unwrap();
        assert_eq!(own, ["scene.pov", "--width", "320", "-o", "a.png", "-q"]);
        assert_eq!((p.width, p.height), (Some(100), Some(240)));
    }

    #[test]
    fn ini_sections_and_switches() {
        let dir = std::env::temp_dir().join(format!("trace-ini-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let ini = dir.join("r.ini");
        std::fs::write(
            &ini,
            "; a comment\nWidth = 320\n+H200\nDeclare=Speed=2.5\n[Big]\nWidth=1920\nheight=1080 ; eh\n",
        )
        .unwrap();
        let p = pov(&[ini.to_str().unwrap()]);
        assert_eq!((p.width, p.height), (Some(320), Some(200)));
        assert_eq!(p.declares, [("Speed".to_string(), 2.5)]);
        // The lines before the first section are read too.
        let p = pov(&[&format!("{}[big]", ini.display())]);
        assert_eq!((p.width, p.height), (Some(1920), Some(1080)));
        assert_eq!(p.declares.len(), 1);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// docs/command-line.md names every option trace reads.
    #[test]
    fn the_documentation_lists_every_option() {
        let doc = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../docs/command-line.md"
        ))
        .expect("docs/command-line.md");
        for (switches, names, _) in OPTIONS {
            for name in names
                .split(", ")
                .chain(switches.split([' ', '/']).filter(|s| s.starts_with('+')))
            {
                let name = name.trim_end_matches("[t]").trim_end_matches("[8|16]");
                assert!(
                    doc.contains(&format!("`{name}")),
                    "docs/command-line.md lacks `{name}`"
                );
            }
        }
    }

    #[test]
    fn unknown_options_are_errors() {
        let split1 = |a: &str| split(vec![a.to_string()], |_| true).map(|_| ());
        assert!(
            split1("+Z3")
                .unwrap_err()
                .contains("unknown POV-Ray switch")
        );
        assert!(
            split1("Frobnicate=1")
                .unwrap_err()
                .contains("unknown POV-Ray option")
        );
        assert!(split1("+FT").unwrap_err().contains("trace writes PNG"));
    }
}
