//! Light sources (pov-semantics §8): point, spot and parallel lights, distance fade,
//! shadowless lights, and area lights with POV-Ray's recursive grid average.

use super::Tracer;
use crate::geometry::Ray;
use crate::scene::{
    AreaLight, Light, LightKind, ObjectId, Queries, Rgb, Scene, ShadowHull, SurfaceHit,
    disc_offset, grid_offset,
};
use glam::DVec3;

/// POV-Ray ignores a light whose cosine with the normal is below this.
const MIN_LIGHT_COSINE: f64 = 1e-10;

/// Two area-light samples differ when their colours differ by more than this (Σ|Δrgb|).
const AREA_DIFFERENCE: f64 = 0.1;

/// What one light contributes at a point, before the surface's finish.
pub struct LightSample {
    /// Unit direction from the point toward the light (its centre for area lights).
    pub direction: DVec3,
    /// Light colour after attenuation and shadows.
    pub colour: Rgb,
    /// Whether the light makes highlights (shadowless lights do not).
    pub highlights: bool,
}

/// Smooth step from `lo` to `hi` (POV-Ray's spotlight edge).
fn smooth_step(lo: f64, hi: f64, p: f64) -> f64 {
    if p < lo {
        0.0
    } else if p >= hi {
        1.0
    } else {
        let s = (p - lo) / (hi - lo);
        s * s * (3.0 - 2.0 * s)
    }
}

/// What can block the shadow rays from a point to a light.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Blockers {
    /// Nothing: every ray reaches the light.
    None,
    /// Only opaque objects, listed in `Tracer::blockers`.
    Opaque,
    /// Objects listed in `Tracer::blockers`, some of which let light through.
    Filtering,
    /// Not known (culling is off, or the pyramid is flat): each ray asks the whole scene.
    Unknown,
}

/// Method 3: points of an area light a pixel's first sample looks at, and how many if they
/// do not all agree.
const AREA_FIRST_POINTS: u32 = 4;
const AREA_FIRST_POINTS_MOST: u32 = 16;

/// An area light's possible blockers found for one point serve the points within this
/// fraction of its distance to the light.
const HULL_REUSE: f64 = 1.0 / 64.0;

/// A point light's: its pyramid is a sliver, and grown four times as far it still holds
/// few objects while serving more points (`glass.rt` at 1280×960, best of three: 0.83 s
/// with 1/64, 0.80 s with 1/32, 0.78–0.79 s with 1/16, 1/8 and 1/4, 0.81 s with 1/2).
const POINT_HULL_REUSE: f64 = 1.0 / 16.0;

/// Pyramids kept per light and object (set), and the most candidates one keeps.
const HULLS_PER_SET: usize = 8;
const HULL_MOST_CANDIDATES: usize = 8;

/// The sets of pyramids kept per light: a point's object picks one (its id modulo the
/// count), so that the points a pixel's rays shade on different objects (its first hit, what
/// that reflects, refracts...) do not push each other's pyramids out.
const HULL_SETS: usize = 8;

/// A light's pyramids found lately, with the possible blockers each holds.
#[derive(Clone, Copy, Default)]
pub(super) struct Hulls {
    sets: [HullSet; HULL_SETS],
}

/// The pyramids kept for points on objects of one set.
#[derive(Clone, Copy, Default)]
struct HullSet {
    kept: [Option<KeptHull>; HULLS_PER_SET],
    /// The slot the next pyramid goes to.
    next: usize,
}

#[derive(Clone, Copy)]
struct KeptHull {
    apex: DVec3,
    /// The squared distance from the apex within which it serves.
    reach2: f64,
    from: Option<ObjectId>,
    kind: Blockers,
    count: usize,
    candidates: [u32; HULL_MOST_CANDIDATES],
}

impl Hulls {
    /// The kind of blockers of a pyramid that serves `apex` on `from`, its candidates put
    /// in `out`.
    fn find(&self, apex: DVec3, from: Option<ObjectId>, out: &mut Vec<u32>) -> Option<Blockers> {
        let kept = self.sets[set(from)]
            .kept
            .iter()
            .flatten()
            .find(|k| k.from == from && (apex - k.apex).length_squared() <= k.reach2)?;
        out.clear();
        out.extend_from_slice(&kept.candidates[..kept.count]);
        Some(kept.kind)
    }

    /// Keeps a pyramid (unless it holds too many candidates).
    fn keep(
        &mut self,
        apex: DVec3,
        reach2: f64,
        from: Option<ObjectId>,
        kind: Blockers,
        list: &[u32],
    ) {
        if list.len() > HULL_MOST_CANDIDATES {
            return;
        }
        let mut candidates = [0; HULL_MOST_CANDIDATES];
        candidates[..list.len()].copy_from_slice(list);
        let set = &mut self.sets[set(from)];
        set.kept[set.next] = Some(KeptHull {
            apex,
            reach2,
            from,
            kind,
            count: list.len(),
            candidates,
        });
        set.next = (set.next + 1) % HULLS_PER_SET;
    }
}

/// The set of pyramids for points on object `from`.
fn set(from: Option<ObjectId>) -> usize {
    from.map_or(0, |o| o.0 as usize % HULL_SETS)
}

/// A hash of a point and two grid indices to [−½, ½)², for deterministic area-light jitter:
/// the same point always gets the same offsets, whatever thread shades it.
fn jitter(p: DVec3, u: u32, v: u32) -> (f64, f64) {
    let mut h: u64 = 0x9E37_79B9_7F4A_7C15;
    for word in [
        p.x.to_bits(),
        p.y.to_bits(),
        p.z.to_bits(),
        ((u as u64) << 32) | v as u64,
    ] {
        h ^= word;
        h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
        h ^= h >> 31;
    }
    let a = (h >> 11) as f64 / (1u64 << 53) as f64;
    let b = ((h.wrapping_mul(0x94D0_49BB_1331_11EB) >> 11) as f64) / (1u64 << 53) as f64;
    (a - 0.5, b - 0.5)
}

/// Where shadow rays leave for a light: a surface (the ray offset off it, toward the side
/// it leaves by) or a point in a medium (a media sample).
#[derive(Clone, Copy)]
pub(super) enum ShadowStart<'h> {
    /// A surface point, seen from a ray that started at the given point.
    Surface(&'h SurfaceHit, DVec3),
    /// A point in space.
    Medium(DVec3),
}

impl ShadowStart<'_> {
    fn point(self) -> DVec3 {
        match self {
            ShadowStart::Surface(hit, _) => hit.point,
            ShadowStart::Medium(p) => p,
        }
    }

    /// The object the point lies on, if any.
    fn object(self) -> Option<ObjectId> {
        match self {
            ShadowStart::Surface(hit, _) => Some(hit.object),
            ShadowStart::Medium(_) => None,
        }
    }

    /// A shadow ray from here along the unit `direction`.
    fn ray(self, scene: &Scene, direction: DVec3) -> Ray {
        match self {
            ShadowStart::Surface(hit, from) => scene.spawn(hit, from, direction),
            ShadowStart::Medium(p) => Ray::new(p, direction),
        }
    }
}

impl Tracer<'_> {
    /// The light `index` as seen from `hit` (normal `n` facing the viewer), or `None` if it
    /// contributes nothing there.
    pub(super) fn light_sample(
        &mut self,
        index: usize,
        hit: &SurfaceHit,
        from: DVec3,
        n: DVec3,
        back: bool,
    ) -> Option<LightSample> {
        let scene = self.scene;
        let light = &scene.lights()[index];
        if light.colour == Rgb::ZERO {
            return None;
        }
        let (direction, distance) = toward(light, hit.point);
        let cos = n.dot(direction);
        if cos < MIN_LIGHT_COSINE && !(back && cos < 0.0) {
            return None;
        }
        let mut colour = light.colour * attenuation(light, hit.point, direction, distance);
        if colour == Rgb::ZERO {
            return None;
        }
        let mut shadow = scene.spawn(hit, from, direction);
        shadow.tmax = reach(light, &shadow, distance)?;
        if !light.shadowless {
            let visible = match &light.area {
                // (Radiosity's rays see an area light as a point light at its centre.)
                Some(area) if area.size1 * area.size2 > 1 && !self.seer.radiosity => {
                    match self.light_stream {
                        Some((seed, n)) => {
                            let start = ShadowStart::Surface(hit, from);
                            self.area_sampled(light, index, area, start, (seed, n))
                        }
                        None => self.area_visibility(
                            (light, index),
                            area,
                            ShadowStart::Surface(hit, from),
                        ),
                    }
                }
                _ => {
                    self.counts.shadow += 1;
                    if self.culls_point_shadows(light) {
                        let start = ShadowStart::Surface(hit, from);
                        let point = || (DVec3::ZERO, DVec3::ZERO);
                        let blockers = self.blockers((light, index), (point, false), start);
                        self.shadow_through(&shadow, light, blockers)
                    } else {
                        self.point_shadow(&shadow, light, index)
                    }
                }
            };
            colour *= visible;
            if colour == Rgb::ZERO {
                return None;
            }
        }
        Some(LightSample {
            direction,
            colour,
            // (Radiosity's rays see no highlights.)
            highlights: !light.shadowless && !self.seer.radiosity,
        })
    }

    /// What reaches the end of a point light's shadow ray (light `index`) that does not
    /// first find its possible blockers: in a scene without transparent objects or media
    /// on shadow rays, by POV-Ray's shadow cache (see [`super::shadow::opaque_transmittance`],
    /// one object a light, kept by the block's tracer).
    fn point_shadow(&mut self, shadow: &Ray, light: &Light, index: usize) -> Rgb {
        if self.media_dims_shadows(light) || self.scene.any_transparent() {
            return self.shadow_seen(shadow, light);
        }
        if self.shadow_cache.len() <= index {
            self.shadow_cache.resize(index + 1, None);
        }
        super::shadow::opaque_transmittance(self.scene, shadow, &mut self.shadow_cache[index])
    }

    /// Whether a point light's shadow rays first find what may block them (see
    /// [`Tracer::blockers`]): in scenes that test every object for every ray (elsewhere a
    /// shading point that finds no pyramid kept, on an object of its own among many, would
    /// pay for a pyramid and a ray), for lights whose shadow rays end at their position, when
    /// no media dims them.
    fn culls_point_shadows(&self, light: &Light) -> bool {
        let point = match &light.kind {
            LightKind::Parallel { .. } | LightKind::Cylinder { .. } => false,
            _ => light.area.is_none(),
        };
        point && self.scene.scans_objects() && !self.media_dims_shadows(light)
    }

    /// What may block the shadow rays from `start` to the light `index` spanning ±`half().0`
    /// and ±`half().1` around its position (zero for a point light; turned to face the point
    /// if `orient`; asked only if no pyramid kept serves the point): the candidates go to
    /// `self.blockers`.
    ///
    /// A point near one seen before takes that point's candidates: each light keeps a few
    /// pyramids grown by a margin (objects outside them cannot meet a ray from any point
    /// within the margin of their apex), so that most shading points of a surface find
    /// their candidates without building a pyramid or testing every object's box against
    /// it. A grown pyramid holds every object the exact one holds, so the rays' answers are
    /// the same; only points it finds blockers for where the exact one finds none trace
    /// rays that all reach the light.
    fn blockers(
        &mut self,
        (light, index): (&Light, usize),
        (half, orient): (impl FnOnce() -> (DVec3, DVec3), bool),
        start: ShadowStart,
    ) -> Blockers {
        if !self.scene.cull_shadow_rays() {
            return Blockers::Unknown;
        }
        let apex = start.point();
        let from = start.object();
        if self.hulls.len() <= index {
            self.hulls.resize(index + 1, Default::default());
        }
        if let Some(kind) = self.hulls[index].find(apex, from, &mut self.blockers) {
            return kind;
        }
        let distance = (light.position - apex).length();
        let reuse = if light.area.is_none() {
            POINT_HULL_REUSE
        } else {
            HULL_REUSE
        };
        let Some(hull) = pyramid(light.position, half(), apex, orient, distance * reuse) else {
            return Blockers::Unknown;
        };
        let mut list = std::mem::take(&mut self.blockers);
        list.clear();
        self.scene.shadow_candidates(&hull, from, &mut list);
        let kind = if list.is_empty() {
            Blockers::None
        } else if self.scene.any_filters_shadows(&list) {
            Blockers::Filtering
        } else {
            Blockers::Opaque
        };
        let reach = distance * reuse;
        self.hulls[index].keep(apex, reach * reach, from, kind, &list);
        self.blockers = list;
        kind
    }

    /// The shadow ray from `start` to the point at offsets (s1, s2) along the light's axes
    /// `a1`, `a2` (already mapped to the disc for circular and oriented lights).
    fn ray_to(
        &self,
        light: &Light,
        (a1, a2): (DVec3, DVec3),
        (s1, s2): (f64, f64),
        start: ShadowStart,
    ) -> Ray {
        let point = light.position + a1 * s1 + a2 * s2;
        let to = point - start.point();
        let length = to.length();
        let mut shadow = start.ray(self.scene, to / length);
        // (The distance from the shaded point, which the ray's origin lies within 10⁻¹² of:
        // one square root a ray, not two, as for a point light.)
        shadow.tmax = length;
        shadow
    }

    /// The shadow ray from `start` to the grid point (u, v) of `area` (axes `axes`), moved
    /// within its cell if the light is jittered.
    fn grid_ray(
        &self,
        light: &Light,
        area: &AreaLight,
        axes: (DVec3, DVec3),
        start: ShadowStart,
        (u, v): (u32, u32),
    ) -> Ray {
        let offsets = match light.grid.get((v * area.size1 + u) as usize) {
            Some(&kept) => kept,
            None => {
                let moved = if area.jitter {
                    jitter(start.point(), u, v)
                } else {
                    (0.0, 0.0)
                };
                grid_offset(area, (u, v), moved)
            }
        };
        self.ray_to(light, axes, offsets, start)
    }

    /// What reaches the end of a shadow ray toward `light` whose possible blockers are
    /// `blockers` (all of them where media may dim it).
    fn shadow_through(&mut self, shadow: &Ray, light: &Light, blockers: Blockers) -> Rgb {
        if self.media_dims_shadows(light) {
            return self.shadow_seen(shadow, light);
        }
        match blockers {
            Blockers::None => Rgb::ONE,
            Blockers::Opaque => self.past_opaque(&super::shadow::blocking_part(shadow)),
            Blockers::Filtering => {
                super::shadow::transmittance_among(self.scene, shadow, &self.blockers)
            }
            Blockers::Unknown => super::transmittance(self.scene, shadow),
        }
    }

    /// What passes the opaque blockers `self.blockers` along `part`, a shadow ray's
    /// blocking part ([`super::shadow::blocking_part`]): all or nothing.
    fn past_opaque(&self, part: &Ray) -> Rgb {
        if self.scene.blocked_among(part, &self.blockers) {
            Rgb::ZERO
        } else {
            Rgb::ONE
        }
    }

    /// The visibility of an area light from points drawn from the pixel's sequence (method 3):
    /// sample `n` of the pixel whose seed is `seed` (a stream of its own for each light) picks
    /// points anywhere on the light, so that the pixel's samples together cover it evenly and
    /// converge on the whole light rather than on its grid.
    pub(super) fn area_sampled(
        &mut self,
        light: &Light,
        index: usize,
        area: &AreaLight,
        origin: ShadowStart,
        (seed, n): (u32, u32),
    ) -> Rgb {
        // The disc mapping's bias moves points up to 0.001 beyond the square.
        let half = |size: u32| if size == 1 { 0.0 } else { 0.502 };
        let half = || {
            let (a1, a2) = grid_axes(light, area, origin.point());
            (a1 * half(area.size1), a2 * half(area.size2))
        };
        let blockers = self.blockers((light, index), (half, area.orient), origin);
        if blockers == Blockers::None {
            return Rgb::ONE;
        }
        let (a1, a2) = grid_axes(light, area, origin.point());
        let light_seed = crate::render::sampler::stream_seed(seed, index as u32 + 1);
        // The pixel's centre sample (the only one most pixels take) looks at 4 points of the
        // light, and at 16 if they disagree; sample n ≥ 1 at one more point, point 16 + n − 1
        // of the light's sequence, so that all of a pixel's points together are a prefix of
        // it.
        let (start, first, most) = if n == 0 {
            (0, AREA_FIRST_POINTS, AREA_FIRST_POINTS_MOST)
        } else {
            (AREA_FIRST_POINTS_MOST + n - 1, 1, 1)
        };
        let mut ray_at = |i: u32| {
            let (mut s1, mut s2) = crate::render::sampler::offset(light_seed, start + i);
            if area.size1 == 1 {
                s1 = 0.0;
            }
            if area.size2 == 1 {
                s2 = 0.0;
            }
            let shadow = self.ray_to(light, (a1, a2), disc_offset(area, (s1, s2)), origin);
            self.counts.shadow += 1;
            self.shadow_through(&shadow, light, blockers)
        };
        let mut sum = Rgb::ZERO;
        let mut seen = None;
        let mut agree = true;
        for i in 0..first {
            let v = ray_at(i);
            agree &= *seen.get_or_insert(v) == v;
            sum += v;
        }
        if agree || most <= first {
            return sum / f64::from(first);
        }
        for i in first..most {
            sum += ray_at(i);
        }
        sum / f64::from(most)
    }

    /// The average visibility (0..1 per channel) of an area light's grid from `hit`, by POV-Ray's
    /// recursive subdivision: grid points get equal weight only for sizes 1, 2, 4, 8, …
    pub(super) fn area_visibility(
        &mut self,
        (light, index): (&Light, usize),
        area: &AreaLight,
        start: ShadowStart,
    ) -> Rgb {
        // Jitter moves grid points up to half a cell beyond the grid's edge, the disc mapping's
        // bias up to 0.001.
        let reach = |size: u32| match (area.jitter, size) {
            (_, 1) => 0.0,
            (true, n) => 0.502 + 0.5 / f64::from(n - 1),
            (false, _) => 0.502,
        };
        // (The grid's axes, turned toward the point if `orient`ed, are worked out once, and
        // only where rays are traced or a pyramid is built.)
        let mut axes = None;
        let mut half = || {
            let (a1, a2) = *axes.get_or_insert_with(|| grid_axes(light, area, start.point()));
            (a1 * reach(area.size1), a2 * reach(area.size2))
        };
        // The possible blockers are found first where the subdivision will trace more than
        // the grid's four corners whatever they see (`adaptive` forces more); otherwise the
        // corners are traced as any shadow ray, and the blockers are found only if the
        // corners differ and more points follow (finding them costs more than four rays
        // among a few objects: a third of POV-Ray's radiosity/cornell.pov without its
        // radiosity, whose corners mostly agree).
        let forced = |size: u32| size.min((1 << area.adaptive.min(30)) + 1);
        let mut blockers = if forced(area.size1) * forced(area.size2) > 4 {
            let found = self.blockers((light, index), (&mut half, area.orient), start);
            if found == Blockers::None {
                return Rgb::ONE;
            }
            Some(found)
        } else {
            None
        };
        let cells = (area.size1 * area.size2) as usize;
        self.area_cache.clear();
        self.area_cache.resize(cells, None);
        let (a1, a2) = *axes.get_or_insert_with(|| grid_axes(light, area, start.point()));
        if let Some(found) = blockers {
            self.trace_forced(light, area, (a1, a2), start, found);
        }
        let mut traced = 0;
        let mut visibility = |tracer: &mut Tracer, u: u32, v: u32| -> Rgb {
            let k = (v * area.size1 + u) as usize;
            if let Some(c) = tracer.area_cache[k] {
                return c;
            }
            traced += 1;
            let blockers = match blockers {
                Some(b) => b,
                None if traced <= 4 => Blockers::Unknown,
                None => {
                    let half = || (a1 * reach(area.size1), a2 * reach(area.size2));
                    let found = tracer.blockers((light, index), (half, area.orient), start);
                    *blockers.insert(found)
                }
            };
            let shadow = tracer.grid_ray(light, area, (a1, a2), start, (u, v));
            tracer.counts.shadow += 1;
            let c = tracer.shadow_through(&shadow, light, blockers);
            tracer.area_cache[k] = Some(c);
            c
        };
        subdivide(
            self,
            &mut visibility,
            area,
            [0, 0, area.size1 - 1, area.size2 - 1],
            0,
        )
    }
    /// Traces the grid points that POV-Ray's subdivision traces whatever they see (the
    /// corners, and the midpoints down to `adaptive` levels) into `area_cache`, together: all
    /// their rays are set up in one pass and tested in the next, so that one ray's square
    /// roots and divisions overlap the next's instead of waiting on the blockers' tests in
    /// between (the set-up was a fifth of `lights.rt`'s time). Grids wider than 64 points
    /// are left to the subdivision, one point at a time.
    fn trace_forced(
        &mut self,
        light: &Light,
        area: &AreaLight,
        axes: (DVec3, DVec3),
        start: ShadowStart,
        blockers: Blockers,
    ) {
        let (Some(us), Some(vs)) = (
            forced_steps(area.size1, area.adaptive),
            forced_steps(area.size2, area.adaptive),
        ) else {
            return;
        };
        // (Behind opaque blockers alone, the rays are cut short of the light here too, and
        // tested straight away.)
        let opaque = blockers == Blockers::Opaque && !self.media_dims_shadows(light);
        let mut rays = std::mem::take(&mut self.area_rays);
        rays.clear();
        for v in bits(vs) {
            for u in bits(us) {
                let ray = self.grid_ray(light, area, axes, start, (u, v));
                let ray = if opaque {
                    super::shadow::blocking_part(&ray)
                } else {
                    ray
                };
                rays.push((v * area.size1 + u, ray));
            }
        }
        self.counts.shadow += rays.len() as u64;
        for (k, ray) in &rays {
            self.area_cache[*k as usize] = Some(if opaque {
                self.past_opaque(ray)
            } else {
                self.shadow_through(ray, light, blockers)
            });
        }
        self.area_rays = rays;
    }
}

/// The pyramid from `apex` to the area light at `c` spanning ±`half.0` and ±`half.1` (a
/// sliver of a square around a point light's `c`), grown to hold the pyramids of every apex
/// within `grow` of `apex` (`None` if flat). An
/// `orient`ed light turns its grid to face each point: its points lie within `r` of its
/// centre in the plane facing the point; for points within `grow` that plane turns by at
/// most asin(grow / distance) ≤ 1.6 grow / distance, which moves them at most that times
/// `r` off the plane facing `apex`, where they project into the square of half-side `r`.
fn pyramid(
    c: DVec3,
    (h1, h2): (DVec3, DVec3),
    apex: DVec3,
    orient: bool,
    grow: f64,
) -> Option<ShadowHull> {
    // A line light (one axis of size 1) gets a sliver of width, so that the hull is solid;
    // a point light a sliver of a square.
    let (h1, h2) = match (h1 == DVec3::ZERO, h2 == DVec3::ZERO) {
        (true, true) => {
            let axis = c - apex;
            let length = axis.length();
            // (An apex at the light, or not finite, has no pyramid.)
            if length.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                return None;
            }
            let side = axis.any_orthogonal_vector().normalize() * (1e-6 * length);
            (side, axis.normalize().cross(side))
        }
        (true, false) => (
            h2.any_orthogonal_vector().normalize() * (1e-6 * h2.length()),
            h2,
        ),
        (false, true) => (
            h1,
            h1.any_orthogonal_vector().normalize() * (1e-6 * h1.length()),
        ),
        (false, false) => (h1, h2),
    };
    let (h1, h2, grow) = if orient && grow > 0.0 {
        let r = std::f64::consts::SQRT_2 * h1.length().max(h2.length());
        let turned = r * 1.6 * grow / (c - apex).length();
        (h1.normalize() * r, h2.normalize() * r, grow + turned)
    } else {
        (h1, h2, grow)
    };
    let corners = [c - h1 - h2, c + h1 - h2, c + h1 + h2, c - h1 + h2];
    Some(ShadowHull::new(apex, corners)?.grown(grow))
}

/// The grid indices along an axis of `size` points that POV-Ray's subdivision reaches
/// whatever the points see (levels below `adaptive` split every rectangle), as bits; `None`
/// for more than 64 points.
fn forced_steps(size: u32, adaptive: u32) -> Option<u64> {
    fn mark(lo: u32, hi: u32, level: u32, adaptive: u32, set: &mut u64) {
        *set |= (1 << lo) | (1 << hi);
        if hi - lo > 1 && level < adaptive {
            mark(lo, (lo + hi) / 2, level + 1, adaptive, set);
            mark((lo + hi).div_ceil(2), hi, level + 1, adaptive, set);
        }
    }
    if size == 0 || size > 64 {
        return None;
    }
    let mut set = 0;
    mark(0, size - 1, 0, adaptive, &mut set);
    Some(set)
}

/// The indices of the set bits of `set`, lowest first.
fn bits(mut set: u64) -> impl Iterator<Item = u32> {
    std::iter::from_fn(move || {
        (set != 0).then(|| {
            let i = set.trailing_zeros();
            set &= set - 1;
            i
        })
    })
}

/// POV-Ray's recursive area-light average over the grid rectangle `r = [u1, v1, u2, v2]`.
fn subdivide<C>(
    tracer: &mut C,
    visibility: &mut impl FnMut(&mut C, u32, u32) -> Rgb,
    area: &AreaLight,
    r: [u32; 4],
    level: u32,
) -> Rgb {
    let [u1, v1, u2, v2] = r;
    let s = [
        visibility(tracer, u1, v1),
        visibility(tracer, u2, v1),
        visibility(tracer, u1, v2),
        visibility(tracer, u2, v2),
    ];
    let differ = |a: Rgb, b: Rgb| (a - b).abs().element_sum() > AREA_DIFFERENCE;
    let corners_differ =
        differ(s[0], s[1]) || differ(s[1], s[3]) || differ(s[3], s[2]) || differ(s[2], s[0]);
    if (u2 - u1 > 1 || v2 - v1 > 1) && (level < area.adaptive || corners_differ) {
        let (ulo, uhi) = ((u1 + u2) / 2, (u1 + u2).div_ceil(2));
        let (vlo, vhi) = ((v1 + v2) / 2, (v1 + v2).div_ceil(2));
        let quads = [
            [u1, v1, ulo, vlo],
            [uhi, v1, u2, vlo],
            [u1, vhi, ulo, v2],
            [uhi, vhi, u2, v2],
        ];
        let mut sum = Rgb::ZERO;
        for q in quads {
            sum += subdivide(tracer, visibility, area, q, level + 1);
        }
        return sum / 4.0;
    }
    (s[0] + s[1] + s[2] + s[3]) / 4.0
}

/// The grid axes, turned to face `p` when the light is `orient`ed (POV-Ray: both axes
/// perpendicular to the direction toward the light, with the length of the first axis).
fn grid_axes(light: &Light, area: &AreaLight, p: DVec3) -> (DVec3, DVec3) {
    if !area.orient {
        return (area.axis1, area.axis2);
    }
    let d = (light.position - p).normalize_or(DVec3::Y);
    let t = if (d.z.abs() - 1.0).abs() < 0.01 {
        DVec3::Y
    } else {
        DVec3::Z
    };
    let a1 = d.cross(t).normalize();
    let a2 = d.cross(a1).normalize();
    let length = area.axis1.length();
    (a1 * length, a2 * length)
}

/// The unit direction from `point` toward `light` and the distance to it (along the
/// light's axis for parallel and cylinder lights).
pub(super) fn toward(light: &Light, point: DVec3) -> (DVec3, f64) {
    match &light.kind {
        LightKind::Parallel { point_at } | LightKind::Cylinder { point_at, .. } => {
            let l = (light.position - *point_at).normalize();
            (l, (light.position - point).dot(l))
        }
        _ => {
            let to = light.position - point;
            let distance = to.length();
            (to / distance, distance)
        }
    }
}

/// How far the shadow ray `shadow` toward `light` (`distance` away) goes: to the light,
/// or with `projected_through` to where it first crosses the object (only what lies before
/// casts shadows); `None` when it does not cross it (no light arrives).
pub(super) fn reach(light: &Light, shadow: &Ray, distance: f64) -> Option<f64> {
    let length = shadow_length(light, distance);
    let Some(through) = &light.through else {
        return Some(length);
    };
    let first = through
        .iter()
        .filter_map(|s| s.first_hit(shadow))
        .reduce(f64::min);
    first.filter(|&t| t < length)
}

/// Spotlight cone, cylinder and distance fade (POV-Ray §8.1–8.2) at `point`.
pub(super) fn attenuation(light: &Light, point: DVec3, direction: DVec3, distance: f64) -> f64 {
    let mut a = 1.0;
    if let LightKind::Cylinder {
        radius,
        falloff,
        tightness,
        ..
    } = &light.kind
    {
        // Nothing behind the light's plane or beyond `falloff` from the axis; a smooth step
        // from `radius` out.
        let axis = light.axis;
        let v = point - light.position;
        let along = v.dot(axis);
        if along <= 0.0 {
            return 0.0;
        }
        let off = (v - along * axis).length();
        if off >= *falloff {
            return 0.0;
        }
        let inside = 1.0 - off / falloff;
        a = inside.powf(*tightness);
        if *radius > 0.0 && off > *radius {
            a *= smooth_step(0.0, 1.0 - radius / falloff, inside);
        }
    }
    if let LightKind::Spot {
        radius_deg,
        tightness,
        ..
    } = &light.kind
    {
        let cos = (-direction).dot(light.axis);
        if cos <= 0.0 {
            return 0.0;
        }
        if *tightness != 0.0 {
            a *= cos.powf(*tightness);
        }
        if *radius_deg < 90.0 && cos < light.cos_radius {
            a *= smooth_step(light.cos_falloff, light.cos_radius, cos);
        }
    }
    if let Some(f) = &light.fade {
        a *= 2.0 / (1.0 + (distance / f.distance).powf(f.power));
    }
    a
}

/// How far a shadow ray toward the light goes: the light's distance from the shaded point.
/// (The ray's origin lies within a rounding offset of the point, under 10⁻¹² of its
/// coordinates, so the ray ends that close to the light; its blocking part ends
/// `SHADOW_TOLERANCE` before it either way. Measured from the origin instead, it took a
/// square root more a shadow ray.)
fn shadow_length(light: &Light, distance: f64) -> f64 {
    match light.kind {
        LightKind::Parallel { .. } | LightKind::Cylinder { .. } => distance.max(0.0),
        _ => distance,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smooth_step_edges() {
        assert_eq!(smooth_step(0.5, 0.8, 0.4), 0.0);
        assert_eq!(smooth_step(0.5, 0.8, 0.9), 1.0);
        assert!((smooth_step(0.5, 0.8, 0.65) - 0.5).abs() < 1e-12);
    }

    fn grid_weights(n: u32, adaptive: u32) -> Vec<f64> {
        let area = AreaLight {
            axis1: DVec3::X,
            axis2: DVec3::Z,
            size1: n,
            size2: n,
            adaptive,
            jitter: false,
            circular: false,
            orient: false,
            area_illumination: false,
        };
        (0..n * n)
            .map(|k| {
                let mut only =
                    |_: &mut (), u: u32, v: u32| if v * n + u == k { Rgb::ONE } else { Rgb::ZERO };
                subdivide(&mut (), &mut only, &area, [0, 0, n - 1, n - 1], 0).x
            })
            .collect()
    }

    #[test]
    fn three_by_three_area_light_weights_are_a_tent() {
        // POV-Ray's recursive average: centre 4/16, edges 2/16, corners 1/16.
        let w = grid_weights(3, 100);
        let expected = [1.0, 2.0, 1.0, 2.0, 4.0, 2.0, 1.0, 2.0, 1.0].map(|x| x / 16.0);
        for (a, b) in w.iter().zip(expected) {
            assert!((a - b).abs() < 1e-12, "{w:?}");
        }
    }

    #[test]
    fn power_of_two_plus_one_grids_are_not_uniform_but_two_by_two_is() {
        assert!(
            grid_weights(2, 100)
                .iter()
                .all(|&w| (w - 0.25).abs() < 1e-12)
        );
        let w = grid_weights(5, 100);
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(w[12] > w[0]);
    }

    /// Finding the possible blockers of an area light's shadow rays first changes no pixel:
    /// planes (the shading one and others), boxes, a torus, a transparent sphere, a jittered
    /// grid, a circular oriented light and a line light, every anti-aliasing method; nor does
    /// it for a point light and a spotlight (in the scene without a top-level index).
    #[test]
    fn culling_shadow_rays_changes_no_pixel() {
        use crate::render::{Antialias, RenderOptions, render, thread_pool};
        let text = "camera { location <0, 3, -6> look_at <0, 0.5, 0> }\n\
            light_source { <-3, 5, -2>, rgb 0.7 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 adaptive 1 jitter }\n\
            light_source { <3, 4, -1>, rgb 0.5 area_light <1, 0, 0>, <0, 1, 0>, 4, 4 adaptive 0 circular orient }\n\
            light_source { <0, 6, 2>, rgb 0.3 area_light <3, 0, 0>, <0, 0, 0>, 6, 1 adaptive 1 }\n\
            light_source { <2.5, 3, -3>, rgb 0.4 }\n\
            light_source { <-1, 2.5, 3>, rgb 0.4 spotlight point_at <0, 0, 0> radius 30 falloff 50 }\n\
            plane { y, 0 pigment { checker rgb 1, rgb 0.3 } }\n\
            plane { -z, -4 pigment { rgb 0.8 } }\n\
            box { <-1.8, 0, -0.4>, <-1, 1.2, 0.4> rotate y * 20 pigment { rgb <0.8, 0.3, 0.2> } }\n\
            torus { 0.5, 0.15 translate <0.6, 0.15, -1.2> pigment { rgb 0.9 } }\n\
            sphere { <1.4, 0.8, 0.5>, 0.8 pigment { rgbf <0.9, 1, 0.9, 0.7> } }\n\
            sphere { <-0.2, 0.4, 1.4>, 0.4 pigment { rgb <0.2, 0.4, 0.9> } }\n";
        let (w, h) = (64, 48);
        // The same scene with a row of small spheres more: enough objects for a top-level
        // BVH, whose nodes the pyramid then culls.
        let row: String = (0..8)
            .map(|k| {
                format!(
                    "sphere {{ <{}, 0.15, 2.5>, 0.15 pigment {{ rgb 0.7 }} }}\n",
                    f64::from(k) * 0.5 - 2.0
                )
            })
            .collect();
        for (text, indexed) in [(text.to_string(), false), (format!("{text}{row}"), true)] {
            let options = crate::LoadOptions {
                width: w,
                height: h,
                ..crate::LoadOptions::default()
            };
            let loaded =
                crate::load_str(std::path::Path::new("cull.rt"), text, &options).expect("loads");
            let scene = crate::scene::Scene::build(&loaded.scene);
            let uncut = crate::scene::Scene::build(&loaded.scene).without_shadow_culling();
            assert_eq!(scene.has_index(), indexed);
            for antialias in [
                Antialias::Off,
                Antialias::Adaptive {
                    threshold: 0.1,
                    depth: 3,
                },
                Antialias::Sampled {
                    threshold: 0.1,
                    depth: 3,
                },
            ] {
                for sampled_lights in [false, true] {
                    let options = RenderOptions {
                        width: w,
                        height: h,
                        antialias,
                        sampled_lights,
                        threads: Some(1),
                        ..RenderOptions::default()
                    };
                    let pool = thread_pool(options.threads).expect("a pool");
                    let culled = render(&scene, &options, &pool);
                    let every_ray = render(&uncut, &options, &pool);
                    let what = format!(
                        "{antialias:?}, sampled {sampled_lights}, index {}",
                        scene.has_index()
                    );
                    assert!(culled.film.pixels == every_ray.film.pixels, "{what}");
                    assert!(
                        culled.stats.counts.shadow < every_ray.stats.counts.shadow,
                        "{what}"
                    );
                }
            }
        }
    }

    /// The points traced together before the subdivision are exactly those it traces when
    /// all points see the same (every size up to 17 by every adaptive level up to 5, grids
    /// of one point by many, and 64 points; none for more).
    #[test]
    fn forced_points_are_those_the_subdivision_always_traces() {
        for (n1, n2) in (1..=17)
            .flat_map(|a| (1..=17).map(move |b| (a, b)))
            .chain([(64, 3)])
        {
            for adaptive in 0..=5 {
                let area = AreaLight {
                    axis1: DVec3::X,
                    axis2: DVec3::Z,
                    size1: n1,
                    size2: n2,
                    adaptive,
                    jitter: false,
                    circular: false,
                    orient: false,
                    area_illumination: false,
                };
                let mut seen = std::collections::BTreeSet::new();
                let mut record = |_: &mut (), u: u32, v: u32| {
                    seen.insert((u, v));
                    Rgb::ONE
                };
                subdivide(&mut (), &mut record, &area, [0, 0, n1 - 1, n2 - 1], 0);
                let (us, vs) = (forced_steps(n1, adaptive), forced_steps(n2, adaptive));
                let forced: std::collections::BTreeSet<(u32, u32)> = bits(us.unwrap())
                    .flat_map(|u| bits(vs.unwrap()).map(move |v| (u, v)))
                    .collect();
                assert_eq!(forced, seen, "{n1}×{n2}, adaptive {adaptive}");
            }
        }
        assert_eq!(forced_steps(65, 3), None);
    }

    /// The pyramid kept for a point under an oriented light (its grid turned to face each
    /// point) keeps every object that the exact pyramid of any point within its reach
    /// keeps (random points, moves and spheres, a fixed seed); without the turn's margin
    /// it does not.
    #[test]
    fn an_oriented_light_s_kept_pyramid_holds_those_of_points_near_it() {
        let mut stream = crate::testing::Xorshift(0x9e37_79b9_7f4a_7c15);
        let mut random = move || stream.unit();
        let mut text = String::from(
            "light_source { <0, 4, 0>, rgb 1 area_light <6, 0, 0>, <0, 6, 0>, 4, 4 \
             circular orient }\n",
        );
        for _ in 0..60 {
            let (x, y, z, r) = (random(), random(), random(), random());
            let (x, y, z) = (6.0 * x - 3.0, 5.0 * y - 1.0, 6.0 * z - 3.0);
            text += &format!("sphere {{ <{x}, {y}, {z}>, {} }}\n", 0.02 + 0.1 * r);
        }
        let scene = crate::testing::scene(text);
        let light = &scene.lights()[0];
        let area = light.area.as_ref().expect("an area light");
        let half = |p: DVec3| {
            let (a1, a2) = grid_axes(light, area, p);
            (a1 * 0.502, a2 * 0.502)
        };
        let (mut near, mut far) = (Vec::new(), Vec::new());
        let mut missed_unturned = 0;
        for _ in 0..4000 {
            let apex = DVec3::new(
                6.0 * random() - 3.0,
                4.0 * random() - 1.0,
                6.0 * random() - 3.0,
            );
            let grow = (light.position - apex).length() * HULL_REUSE * 8.0 * random();
            let turn = DVec3::new(random() - 0.5, random() - 0.5, random() - 0.5);
            let moved = apex + turn.normalize() * grow * random().sqrt();
            let c = light.position;
            let (Some(kept), Some(unturned), Some(exact)) = (
                pyramid(c, half(apex), apex, true, grow),
                pyramid(c, half(apex), apex, false, grow),
                pyramid(c, half(moved), moved, false, 0.0),
            ) else {
                continue;
            };
            near.clear();
            scene.shadow_candidates(&exact, None, &mut near);
            far.clear();
            scene.shadow_candidates(&kept, None, &mut far);
            assert!(
                near.iter().all(|i| far.contains(i)),
                "{apex} {moved} {grow}"
            );
            far.clear();
            scene.shadow_candidates(&unturned, None, &mut far);
            missed_unturned += usize::from(!near.iter().all(|i| far.contains(i)));
        }
        assert!(missed_unturned > 0);
    }

    #[test]
    fn jitter_is_deterministic_and_in_range() {
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert_eq!(jitter(p, 1, 2), jitter(p, 1, 2));
        let (a, b) = jitter(p, 3, 4);
        assert!((-0.5..0.5).contains(&a) && (-0.5..0.5).contains(&b));
    }
}
