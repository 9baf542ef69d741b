//! PlacedPigment evaluation: the colour of a pattern at a point (POV-Ray §12.2). It lives beside
//! the patterns so that a pigment function (`function { pigment { … } }`) is made while the
//! scene is read, as data, and the render-ready materials use the same evaluation.

use super::image::ImageMap;
use super::{Pattern, PatternKind, Surface};
use glam::{DMat4, DVec3};
use std::sync::Arc;

/// An RGB colour (linear working space, unclamped).
pub type Rgb = DVec3;

/// A POV-Ray colour with its five channels: red, green, blue, filter, transmit.
///
/// `.rt`: `color rgbft <r, g, b, f, t>`, `rgb <r, g, b>`, `rgbf`, `rgbt`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Colour {
    /// Red, green, blue.
    pub rgb: Rgb,
    /// Light passing through, tinted by `rgb`.
    pub filter: f64,
    /// Light passing through untinted.
    pub transmit: f64,
}

/// A pigment placed in the world (made from the IR's pigment by `ir::PlacedPigment::placed`).
#[derive(Clone, Debug, PartialEq)]
pub struct PlacedPigment {
    kind: Kind,
    /// Pattern space from world space; `None` is the identity.
    pattern_from_world: Option<Box<DMat4>>,
}

#[derive(Clone, Debug, PartialEq)]
enum Kind {
    Solid(Colour),
    /// A pattern's value looked up in its map.
    Pattern(Box<Mapped>),
    Image(Arc<ImageMap>),
}

/// A pattern and the entries its values are looked up in.
#[derive(Clone, Debug, PartialEq)]
struct Mapped {
    pattern: Pattern,
    map: Map,
}

/// A pattern's map: (value, colour) or (value, pigment) entries.
#[derive(Clone, Debug, PartialEq)]
pub enum Map {
    /// `color_map`.
    Colours(Box<[(f64, Colour)]>),
    /// `pigment_map`: pigments placed in the pattern's space.
    Pigments(Box<[(f64, PlacedPigment)]>),
}

impl PlacedPigment {
    /// One colour everywhere (`pattern_from_world` is kept, as POV-Ray keeps a solid
    /// pigment's transformation, but not used).
    pub fn solid(colour: Colour, pattern_from_world: Option<DMat4>) -> PlacedPigment {
        PlacedPigment::placed(Kind::Solid(colour), pattern_from_world)
    }

    /// The colour everywhere, for a solid pigment.
    #[inline]
    pub fn solid_colour(&self) -> Option<&Colour> {
        match &self.kind {
            Kind::Solid(c) => Some(c),
            _ => None,
        }
    }

    /// A pattern's value looked up in its map.
    pub fn mapped(pattern: Pattern, map: Map, pattern_from_world: Option<DMat4>) -> PlacedPigment {
        let kind = Kind::Pattern(Box::new(Mapped { pattern, map }));
        PlacedPigment::placed(kind, pattern_from_world)
    }

    /// An image map.
    pub fn image(image: Arc<ImageMap>, pattern_from_world: Option<DMat4>) -> PlacedPigment {
        PlacedPigment::placed(Kind::Image(image), pattern_from_world)
    }

    fn placed(kind: Kind, pattern_from_world: Option<DMat4>) -> PlacedPigment {
        PlacedPigment {
            kind,
            pattern_from_world: pattern_from_world.map(Box::new),
        }
    }

    /// Whether the pigment (or one inside it) is uv-mapped.
    pub fn uses_uv(&self) -> bool {
        match &self.kind {
            Kind::Pattern(m) => {
                m.pattern.kind == PatternKind::UvMapping
                    || matches!(&m.map, Map::Pigments(ps) if ps.iter().any(|(_, p)| p.uses_uv()))
            }
            _ => false,
        }
    }

    /// Whether the pigment (or one inside it) is a slope or aoi pattern: its colour depends on
    /// the surface's normal and the ray, not only the point.
    pub fn uses_surface(&self) -> bool {
        match &self.kind {
            Kind::Pattern(m) => {
                matches!(m.pattern.kind, PatternKind::Slope(_) | PatternKind::Aoi)
                    || matches!(&m.map, Map::Pigments(ps) if ps.iter().any(|(_, p)| p.uses_surface()))
            }
            _ => false,
        }
    }

    /// Whether the pigment may let light through somewhere (filter or transmit non-zero).
    pub fn may_be_transparent(&self) -> bool {
        let see_through = |c: &Colour| c.filter != 0.0 || c.transmit != 0.0;
        match &self.kind {
            Kind::Solid(c) => see_through(c),
            Kind::Pattern(m) => match &m.map {
                Map::Colours(cs) => cs.iter().any(|(_, c)| see_through(c)),
                Map::Pigments(ps) => ps.iter().any(|(_, p)| p.may_be_transparent()),
            },
            Kind::Image(_) => true,
        }
    }

    /// Whether the pigment is one colour everywhere.
    pub fn is_solid(&self) -> bool {
        matches!(self.kind, Kind::Solid(_))
    }

    /// The colour at world point `p`, off any surface.
    pub fn colour_at(&self, p: DVec3) -> Colour {
        self.colour_on(p, &Surface::default())
    }

    /// The colour at world point `p` of `surface`.
    pub fn colour_on(&self, p: DVec3, surface: &Surface) -> Colour {
        if let Some(c) = self.solid_colour() {
            return *c;
        }
        let q = self
            .pattern_from_world
            .as_ref()
            .map_or(p, |m| m.transform_point3(p));
        match &self.kind {
            Kind::Solid(c) => *c,
            // `uv_mapping`: the entry sees the surface's (u, v, 0), whatever moved the pigment.
            Kind::Pattern(m) if matches!(m.pattern.kind, PatternKind::UvMapping) => match &m.map {
                Map::Pigments(ps) => ps[0].1.colour_on(surface.uv.extend(0.0), surface),
                Map::Colours(cs) => cs[0].1,
            },
            Kind::Pattern(m) if matches!(m.pattern.kind, PatternKind::Average) => {
                // POV-Ray's average: the entries weighted by their values.
                let w = m.pattern.warp(q);
                match &m.map {
                    Map::Colours(cs) => average(cs.iter().map(|(v, c)| (*v, *c))),
                    Map::Pigments(ps) => {
                        average(ps.iter().map(|(v, p)| (*v, p.colour_on(w, surface))))
                    }
                }
            }
            Kind::Pattern(m) => match &m.map {
                Map::Colours(cs) => lookup(cs, m.pattern.value_on(q, surface)),
                Map::Pigments(ps) => {
                    // The entries' pigments see the point in the pattern's space, after its
                    // warps (POV-Ray's Compute_Pigment for a pigment map).
                    let w = m.pattern.warp(q);
                    let v = m.pattern.wave.apply(m.pattern.raw_on(w, surface));
                    let (prev, cur, t) = search(ps, v);
                    let c1 = ps[cur].1.colour_on(w, surface);
                    if prev == cur {
                        c1
                    } else {
                        blend(ps[prev].1.colour_on(w, surface), c1, t)
                    }
                }
            },
            Kind::Image(image) => image_colour(image, q),
        }
    }
}

/// `function { pigment { … } }`: the pigment's colour at a point, as a function of x, y, z
/// giving red, green, blue, filter and transmit (POV-Ray's pigment functions).
#[derive(Debug, PartialEq)]
pub struct PigmentFunction(pub PlacedPigment);

impl crate::func::Native for PigmentFunction {
    fn params(&self) -> usize {
        3
    }

    fn size(&self) -> usize {
        5
    }

    fn eval(&self, args: &[f64], _generator: u8) -> [f64; 5] {
        let c = self.0.colour_at(DVec3::new(args[0], args[1], args[2]));
        [c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit]
    }

    fn same(&self, other: &dyn crate::func::Native) -> bool {
        crate::func::same_data(self, other)
    }
}

/// The colour map at `v`: the first colour below the first entry, the last at or above the
/// last, otherwise linear interpolation of all five channels toward the first entry whose
/// value is ≥ v (so of two entries with the same value, the earlier wins exactly there).
pub fn lookup(entries: &[(f64, Colour)], v: f64) -> Colour {
    let (prev, cur, t) = search(entries, v);
    if prev == cur {
        entries[cur].1
    } else {
        blend(entries[prev].1, entries[cur].1, t)
    }
}

/// The mean of colours weighted by their weights (POV-Ray's `average`).
fn average(weighted: impl Iterator<Item = (f64, Colour)>) -> Colour {
    let (mut sum, mut total) = (Colour::default(), 0.0);
    for (w, c) in weighted {
        sum.rgb += c.rgb * w;
        sum.filter += c.filter * w;
        sum.transmit += c.transmit * w;
        total += w;
    }
    Colour {
        rgb: sum.rgb / total,
        filter: sum.filter / total,
        transmit: sum.transmit / total,
    }
}

/// `a` to `b` by `t`, in all five channels.
fn blend(a: Colour, b: Colour, t: f64) -> Colour {
    Colour {
        rgb: a.rgb + (b.rgb - a.rgb) * t,
        filter: a.filter + (b.filter - a.filter) * t,
        transmit: a.transmit + (b.transmit - a.transmit) * t,
    }
}

/// POV-Ray's `Search_Blend_Map`: the entries around `v` and the fraction of the way from the
/// first to the second (`prev == cur`: that entry alone).
pub fn search<T>(entries: &[(f64, T)], v: f64) -> (usize, usize, f64) {
    // It also defines maps whose keys decrease: at or above the last key, the last entry;
    // otherwise scan from the first entry to the first key not below `v` and blend with the
    // entry scanned before it.
    let last = entries.len() - 1;
    if v >= entries[last].0 {
        return (last, last, 0.0);
    }
    let (mut prev, mut cur) = (0, 0);
    while v > entries[cur].0 {
        prev = cur;
        cur += 1;
    }
    if prev == cur || v == entries[cur].0 {
        return (cur, cur, 0.0);
    }
    (
        prev,
        cur,
        (v - entries[prev].0) / (entries[cur].0 - entries[prev].0),
    )
}

/// An image map (POV-Ray's `image_map`): the image's pixel, fully
/// transparent white off a `once` image.
fn image_colour(image: &ImageMap, q: DVec3) -> Colour {
    match image.at(q) {
        Some(px) => Colour {
            rgb: Rgb::new(px[0] as f64, px[1] as f64, px[2] as f64),
            filter: px[3] as f64,
            transmit: px[4] as f64,
        },
        None => Colour {
            rgb: Rgb::ONE,
            filter: 0.0,
            transmit: 1.0,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(v: f64) -> Colour {
        Colour {
            rgb: Rgb::splat(v),
            filter: 0.0,
            transmit: 0.0,
        }
    }

    #[test]
    fn checker_picks_its_two_colours_by_unit_cube() {
        let p = PlacedPigment::mapped(
            Pattern::new(PatternKind::Checker),
            Map::Colours([(0.0, c(0.2)), (1.0, c(0.7))].into()),
            None,
        );
        assert_eq!(p.colour_at(DVec3::new(0.5, 0.5, 0.5)), c(0.2));
        assert_eq!(p.colour_at(DVec3::new(1.5, 0.5, 0.5)), c(0.7));
        assert_eq!(p.colour_at(DVec3::new(-0.5, 0.5, 0.5)), c(0.7));
    }

    #[test]
    fn colour_map_interpolates_and_clamps() {
        let map = [(0.2, c(0.0)), (0.6, c(1.0))];
        assert_eq!(lookup(&map, 0.0), c(0.0));
        assert!((lookup(&map, 0.4).rgb.x - 0.5).abs() < 1e-12);
        assert_eq!(lookup(&map, 0.9), c(1.0));
        // Two entries at the same value: the earlier one wins exactly at that value.
        let map = [(0.0, c(0.0)), (0.5, c(0.2)), (0.5, c(0.8)), (1.0, c(1.0))];
        assert_eq!(lookup(&map, 0.5), c(0.2));
        assert!(lookup(&map, 0.5000001).rgb.x > 0.79);
    }

    #[test]
    fn colour_map_with_decreasing_keys_reads_as_povray() {
        // [0 c0] [0.6 c0.6] [0.3 c0.3] [1 c1]: POV-Ray blends 0 → 0.6 below 0.6, then 0.3 → 1
        // (measured: at 0.61 it shows 44% of the way from the 0.3 colour to the 1 colour).
        let map = [(0.0, c(0.0)), (0.6, c(0.6)), (0.3, c(0.3)), (1.0, c(1.0))];
        assert!((lookup(&map, 0.3).rgb.x - 0.3).abs() < 1e-12);
        assert!((lookup(&map, 0.59).rgb.x - 0.59).abs() < 1e-12);
        let at = lookup(&map, 0.61).rgb.x;
        assert!((at - (0.3 + 0.7 * (0.31 / 0.7))).abs() < 1e-12, "{at}");
        // Keys 0.8 then 0.2: below 0.2 the first colour, from 0.2 on the last.
        let map = [(0.8, c(0.0)), (0.2, c(1.0))];
        assert_eq!(lookup(&map, 0.1), c(0.0));
        assert_eq!(lookup(&map, 0.5), c(1.0));
    }
}
