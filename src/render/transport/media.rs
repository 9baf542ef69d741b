//! Participating media along a ray segment, as POV-Ray 3.7.0 integrates them (its
//! `MediaFunction`, docs/media.md): the parts of the segment lit by spot and cylinder
//! lights, intervals shared out between lit and unlit parts by `ratio`, then per interval
//! method 3's adaptive samples (with 3.7.0's own quirks: the last 1/(S+1) of an interval is
//! never sampled, the attenuation within it is a left Riemann sum) or methods 1 and 2's
//! regular ones, and the intervals combined front to back. At each sample the media's
//! densities give extinction, emission and scattering; scattering adds the light of every
//! light whose lit part holds the sample, seen through a shadow ray (which starts in the
//! viewing ray's media) and weighted by the phase functions' mean.
//!
//! Shadow rays see media too (`shadow_media`): the interior media of the objects the ray is
//! inside over each stretch between the surfaces it crosses, and the atmosphere for lights
//! with `media_attenuation`.

use super::Tracer;
use super::fog::fog_attenuation;
use super::lights::ShadowStart;
use super::medium::MediumStack;
use super::shadow::SHADOW_TOLERANCE;
use crate::geometry::Ray;
use crate::scene::{Light, LightKind, Media, ObjectId, Rgb, ShadowCrossing};
use glam::DVec3;

/// POV-Ray's `MAX_DISTANCE`: how far a lit part may reach.
const MAX_DISTANCE: f64 = 1e7;
/// POV-Ray's `SMALL_TOLERANCE`: a light's part must end beyond this.
const SMALL_TOLERANCE: f64 = 1e-3;
/// POV-Ray's `EPSILON` (a quadric's discriminant within it is a tangent).
const EPSILON: f64 = 1e-10;

/// A stretch of a ray seen through media: from `origin` along the unit `direction`,
/// `depth` long.
pub(super) struct Segment<'s> {
    pub(super) origin: DVec3,
    pub(super) direction: DVec3,
    pub(super) depth: f64,
    /// A shadow ray: only the dimming counts (no emission, no scattering).
    pub(super) shadow: bool,
    /// The media the viewing ray is in: where the shadow rays of its samples start.
    pub(super) inside: &'s MediumStack,
    /// The object the ray ends on, whose light groups choose the lights that scatter.
    pub(super) hit: Option<ObjectId>,
}

/// The part of a segment a light reaches (POV-Ray's light source entry).
struct LitPart {
    light: usize,
    s0: f64,
    s1: f64,
}

/// A tracer's reusable lists for media (no allocation per ray once they have grown): one
/// set for viewing rays and one for the shadow rays their samples send (which run while a
/// viewing ray's are in use).
#[derive(Default)]
pub(super) struct Scratch<'a> {
    /// Media pooled from the objects a ray is inside: [viewing, shadow].
    pooled: [Vec<&'a Media>; 2],
    /// Sampling intervals: [viewing, shadow].
    intervals: [Vec<Interval>; 2],
    /// Lit and unlit parts of the ray: [viewing, shadow].
    lit: [Vec<LitInterval>; 2],
    lights: Vec<LitPart>,
    ends: (Vec<f64>, Vec<f64>),
}

/// The media one call pools: the atmosphere's, or those of the objects a ray is inside.
#[derive(Clone, Copy)]
pub(super) enum MediaList<'m, 'a> {
    /// A list of media held by the scene (the atmosphere).
    Held(&'a [Media]),
    /// Media gathered from several objects.
    Gathered(&'m [&'a Media]),
}

impl<'a> MediaList<'_, 'a> {
    fn len(self) -> usize {
        match self {
            MediaList::Held(m) => m.len(),
            MediaList::Gathered(m) => m.len(),
        }
    }

    fn get(self, i: usize) -> &'a Media {
        match self {
            MediaList::Held(m) => &m[i],
            MediaList::Gathered(m) => m[i],
        }
    }

    fn iter(self) -> impl Iterator<Item = &'a Media> {
        (0..self.len()).map(move |i| self.get(i))
    }
}

/// A lit or unlit part of a segment.
struct LitInterval {
    lit: bool,
    s0: f64,
    s1: f64,
}

/// A media interval and what its samples gathered.
#[derive(Clone, Copy)]
struct Interval {
    lit: bool,
    s0: f64,
    ds: f64,
    /// Optical depth.
    od: Rgb,
    /// Light emitted and scattered toward the viewer.
    te: Rgb,
    /// Sum of the squared sample colours (methods 1 and 2).
    te2: Rgb,
    samples: u32,
}

/// The deterministic numbers where POV-Ray draws random ones (media's method 1, jitter; a
/// rainbow's jitter): a hash of the ray, so the same ray gets the same numbers on any thread.
pub(super) struct Numbers(u64);

impl Numbers {
    fn new(seg: &Segment) -> Numbers {
        Numbers::along(seg.origin, seg.direction)
    }

    /// The numbers of the ray from `origin` along `direction`.
    pub(super) fn along(origin: DVec3, direction: DVec3) -> Numbers {
        let mut h: u64 = 0x243F_6A88_85A3_08D3;
        for w in [
            origin.x,
            origin.y,
            origin.z,
            direction.x,
            direction.y,
            direction.z,
        ] {
            h = (h ^ w.to_bits()).wrapping_mul(0x9E37_79B9_7F4A_7C15);
            h ^= h >> 29;
        }
        Numbers(h)
    }

    /// The next number in [0, 1).
    pub(super) fn next(&mut self) -> f64 {
        // (splitmix64)
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Σ|Δ| over the channels (POV-Ray's colour distance).
fn distance(a: Rgb, b: Rgb) -> f64 {
    (a - b).abs().element_sum()
}

/// e^v channel by channel (once for a grey v: media are mostly grey).
fn exp(v: Rgb) -> Rgb {
    if v.x == v.y && v.y == v.z {
        return Rgb::splat(v.x.exp());
    }
    Rgb::new(v.x.exp(), v.y.exp(), v.z.exp())
}

/// What the pooled media of one call share (POV-Ray takes them from the medium with the
/// most intervals).
struct Pool<'m, 'a> {
    media: MediaList<'m, 'a>,
    /// The first medium with the most intervals.
    lead: &'a Media,
    aa_threshold: f64,
    scatters: bool,
}

impl<'a> Tracer<'a> {
    /// `colour`, seen at the end of `seg` through `media` (POV-Ray's ComputeMedia): dimmed by
    /// their optical depth, plus what they emit and scatter toward the viewer. Also returns
    /// the transmittance.
    pub(super) fn through_media(
        &mut self,
        media: MediaList<'_, 'a>,
        seg: &Segment,
        colour: Rgb,
    ) -> (Rgb, Rgb) {
        if media.len() == 0 {
            return (colour, Rgb::ONE);
        }
        let mut lead = media.get(0);
        let mut pool_threshold = f64::INFINITY;
        let (mut dims, mut scatters, mut plain) = (false, false, seg.shadow);
        for m in media.iter() {
            if m.intervals > lead.intervals {
                lead = m;
            }
            pool_threshold = pool_threshold.min(m.aa_threshold);
            dims |= m.dims;
            scatters |= m.scatters;
            plain &= m.plain_head();
        }
        if seg.shadow && !dims {
            return (colour, Rgb::ONE);
        }
        let pool = Pool {
            media,
            lead,
            aa_threshold: pool_threshold,
            scatters,
        };
        let which = usize::from(seg.shadow);
        let mut lights = std::mem::take(&mut self.media_scratch.lights);
        let mut lit = std::mem::take(&mut self.media_scratch.lit[which]);
        let mut intervals = std::mem::take(&mut self.media_scratch.intervals[which]);
        lights.clear();
        lit.clear();
        if !seg.shadow {
            self.lit_parts(seg, &mut lights, &mut lit);
        }
        if lit.is_empty() {
            lit.push(LitInterval {
                lit: false,
                s0: 0.0,
                s1: seg.depth,
            });
        }
        sample_intervals(&lit, lead, &mut intervals);
        let mut numbers = Numbers::new(seg);
        if lead.method == 3 && !plain {
            self.adaptive(&pool, &lights, &mut intervals, seg, &mut numbers);
        } else {
            self.regular(&pool, &lights, &mut intervals, seg, plain, &mut numbers);
        }
        // Front to back: each interval's light dimmed by the intervals before it.
        let (mut od, mut te) = (Rgb::ZERO, Rgb::ZERO);
        for i in &intervals {
            let n = 1.0 / f64::from(i.samples);
            te += i.te * n * exp(-od);
            od += i.od * n;
        }
        self.media_scratch.lights = lights;
        self.media_scratch.lit[which] = lit;
        self.media_scratch.intervals[which] = intervals;
        let t = exp(-od);
        (colour * t + te, t)
    }

    /// The media of the objects in `list`, pooled (for a viewing or a shadow ray): give the
    /// list back with [`Tracer::give_pooled`].
    pub(super) fn pooled(&mut self, list: &MediumStack, shadow: bool) -> Vec<&'a Media> {
        let scene = self.scene;
        let mut pooled = std::mem::take(&mut self.media_scratch.pooled[usize::from(shadow)]);
        pooled.clear();
        for id in list.objects() {
            pooled.extend(scene.media_in(id));
        }
        pooled
    }

    pub(super) fn give_pooled(&mut self, pooled: Vec<&'a Media>, shadow: bool) {
        self.media_scratch.pooled[usize::from(shadow)] = pooled;
    }

    /// The lights that scatter in the media along `seg`, each with the part of the segment
    /// it reaches, and those parts merged into lit and unlit intervals (POV-Ray's
    /// ComputeMediaLightInterval, whose merge sorts the starts and the ends apart).
    fn lit_parts(&mut self, seg: &Segment, lights: &mut Vec<LitPart>, lit: &mut Vec<LitInterval>) {
        let scene = self.scene;
        for (index, light) in scene.lights().iter().enumerate() {
            let lights_it = match seg.hit {
                Some(id) => scene.object(id).lit_by(light),
                None => light.group.is_none(),
            };
            if !light.media_interaction || light.shadowless || !lights_it {
                continue;
            }
            let part = match &light.kind {
                LightKind::Spot { .. } => {
                    spot_part(seg, light.position, light.axis, light.cos_falloff)
                }
                LightKind::Cylinder { falloff, .. } => {
                    cylinder_part(seg, light.position, light.axis, *falloff)
                }
                LightKind::Point | LightKind::Parallel { .. } => Some((0.0, seg.depth)),
            };
            match part {
                Some((t1, t2)) if t1 < seg.depth && t2 > SMALL_TOLERANCE => lights.push(LitPart {
                    light: index,
                    s0: t1.max(0.0),
                    s1: t2.min(seg.depth),
                }),
                _ => {}
            }
        }
        if lights.is_empty() {
            return;
        }
        let (s0, s1) = &mut self.media_scratch.ends;
        s0.clear();
        s1.clear();
        s0.extend(lights.iter().map(|l| l.s0));
        s1.extend(lights.iter().map(|l| l.s1));
        s0.sort_by(f64::total_cmp);
        s1.sort_by(f64::total_cmp);
        if s0[0] > 0.0 {
            lit.push(LitInterval {
                lit: false,
                s0: 0.0,
                s1: s0[0],
            });
        }
        lit.push(LitInterval {
            lit: true,
            s0: s0[0],
            s1: s1[0],
        });
        for i in 1..lights.len() {
            let end = lit.last().map_or(0.0, |l| l.s1);
            if s0[i] > end {
                lit.push(LitInterval {
                    lit: false,
                    s0: end,
                    s1: s0[i],
                });
                lit.push(LitInterval {
                    lit: true,
                    s0: s0[i],
                    s1: s1[i],
                });
            } else if s1[i] > end {
                if let Some(last) = lit.last_mut() {
                    last.s1 = s1[i];
                }
            }
        }
        let end = lit.last().map_or(0.0, |l| l.s1);
        if end < seg.depth {
            lit.push(LitInterval {
                lit: false,
                s0: end,
                s1: seg.depth,
            });
        }
    }

    /// Method 3 (POV-Ray 3.7.0's ComputeMediaAdaptiveSampling).
    fn adaptive(
        &mut self,
        pool: &Pool<'_, 'a>,
        lights: &[LitPart],
        intervals: &mut [Interval],
        seg: &Segment,
        numbers: &mut Numbers,
    ) {
        let lead = pool.lead;
        let jitter = lead.jitter;
        for i in intervals.iter_mut() {
            self.counts.media_intervals += 1;
            let count = (lead.samples.0 / 2 + 1).max(2);
            // (3.7.0 steps by 1/(S+1): the interval's last step is never sampled.)
            let dd = 1.0 / f64::from(count + 1);
            let mut d0 = 0.0;
            let u = numbers.next();
            let (mut c0, mut o0) =
                self.sample(pool, lights, i, seg, d0 + dd * jitter * (u - 0.5), 3);
            i.te = Rgb::ZERO;
            i.od = Rgb::ZERO;
            let n = 1.0 / f64::from(count);
            d0 += dd;
            for _ in 1..=count {
                let u = numbers.next();
                let (c1, o1) = self.sample(pool, lights, i, seg, d0 + dd * jitter * (u - 0.5), 3);
                let ends = ((d0 - dd, d0), (c0, c1), (o0, o1));
                let (r, o) = self.refine(
                    pool,
                    lights,
                    i,
                    seg,
                    ends,
                    lead.aa_level as i32 - 1,
                    numbers,
                );
                // (Left Riemann: this step dimmed by the steps before it only.)
                i.te += r * exp(-i.od * n);
                c0 = c1;
                i.od += o;
                o0 = o1;
                d0 += dd;
            }
            i.samples = count;
        }
    }

    /// Method 3's recursive refinement of a step between two samples: a sample at its
    /// middle, and each half refined again where its ends' colours differ by more than the
    /// threshold (POV-Ray's weights, 1/3 and 1/6, kept).
    #[allow(clippy::too_many_arguments)]
    fn refine(
        &mut self,
        pool: &Pool<'_, 'a>,
        lights: &[LitPart],
        i: &mut Interval,
        seg: &Segment,
        ((d1, d3), (c1, c3), (o1, o3)): ((f64, f64), (Rgb, Rgb), (Rgb, Rgb)),
        depth: i32,
        numbers: &mut Numbers,
    ) -> (Rgb, Rgb) {
        let d2 = 0.5 * (d1 + d3);
        let u = numbers.next();
        let at = d2 + pool.lead.jitter * (d3 - d1) * (u - 0.5);
        let (c2, o2) = self.sample(pool, lights, i, seg, at, 3);
        if depth <= 0 {
            return ((c1 + c2 + c3) / 3.0, (o1 + o2 + o3) / 3.0);
        }
        let thr = pool.aa_threshold;
        let (mut r, mut o) = if distance(c1, c2) > thr {
            let (r2, o2r) = self.refine(
                pool,
                lights,
                i,
                seg,
                ((d1, d2), (c1, c2), (o1, o2)),
                depth - 1,
                numbers,
            );
            (r2 / 2.0, o2r / 2.0)
        } else {
            (c1 / 3.0 + c2 / 6.0, o1 / 3.0 + o2 / 6.0)
        };
        if distance(c2, c3) > thr {
            let (r2, o2r) = self.refine(
                pool,
                lights,
                i,
                seg,
                ((d2, d3), (c2, c3), (o2, o3)),
                depth - 1,
                numbers,
            );
            r += r2 / 2.0;
            o += o2r / 2.0;
        } else {
            r += c2 / 6.0 + c3 / 3.0;
            o += o2 / 6.0 + o3 / 3.0;
        }
        (r, o)
    }

    /// Methods 1 and 2 (POV-Ray's ComputeMediaRegularSampling): `samples` per interval,
    /// random (method 1) or one in each equal part (method 2), then more random ones while
    /// the samples' variance is above the confidence test's threshold. A shadow ray through
    /// media whose last density is plain takes one sample per interval.
    fn regular(
        &mut self,
        pool: &Pool<'_, 'a>,
        lights: &[LitPart],
        intervals: &mut [Interval],
        seg: &Segment,
        plain: bool,
        numbers: &mut Numbers,
    ) {
        let lead = pool.lead;
        let (min, max) = lead.samples;
        self.counts.media_intervals += intervals.len() as u64;
        for i in intervals.iter_mut() {
            for j in 0..min {
                let u = numbers.next();
                if lead.method == 2 {
                    let d0 =
                        (f64::from(j) + 0.5) / f64::from(min) + u * lead.jitter / f64::from(min);
                    self.sample(pool, lights, i, seg, d0, 2);
                } else {
                    self.sample(pool, lights, i, seg, u, 1);
                }
                if plain {
                    break;
                }
            }
        }
        if seg.shadow || max <= min {
            return;
        }
        for i in intervals.iter_mut() {
            if i.samples >= max {
                continue;
            }
            let variance = |i: &Interval| {
                let n = 1.0 / f64::from(i.samples);
                (i.te2 * n - (i.te * n) * (i.te * n)) * n
            };
            let mut va = variance(i);
            while va.max_element() >= lead.thresholds[(i.samples - 1) as usize] {
                let u = numbers.next();
                self.sample(pool, lights, i, seg, u, 1);
                if i.samples > max {
                    break;
                }
                va = variance(i);
            }
        }
    }

    /// One sample at fraction `d0` of interval `i` (POV-Ray's ComputeOneMediaSample): the
    /// light it sends toward the viewer over the whole interval and the interval's optical
    /// depth as seen there. Methods 1 and 2 add both to the interval themselves.
    fn sample(
        &mut self,
        pool: &Pool<'_, 'a>,
        lights: &[LitPart],
        i: &mut Interval,
        seg: &Segment,
        d0: f64,
        method: u32,
    ) -> (Rgb, Rgb) {
        self.counts.media_samples += 1;
        let d0 = d0 * i.ds;
        let t = i.s0 + d0;
        let p = seg.origin + seg.direction * t;
        let (mut extinction, mut emission, mut scattering) = (Rgb::ZERO, Rgb::ZERO, Rgb::ZERO);
        for m in pool.media.iter() {
            let rho = m.density(p);
            extinction += rho * m.extinction;
            if !seg.shadow {
                emission += rho * m.emission;
                scattering += rho * m.scattering;
            }
        }
        let od = extinction * i.ds;
        if method != 3 {
            i.od += od;
        }
        if !seg.shadow && pool.scatters && i.lit {
            for part in lights {
                if t < part.s0 || t > part.s1 {
                    continue;
                }
                if let Some((toward, light)) = self.media_light(part.light, p, seg.inside) {
                    let alpha = toward.dot(seg.direction);
                    let k = (pool.media.iter())
                        .map(|m| m.phase.value(alpha))
                        .sum::<f64>()
                        / pool.media.len() as f64;
                    emission += scattering * light * k;
                }
            }
        }
        let c = if method == 3 {
            emission * i.ds
        } else {
            // (Assumes the extinction is the same from the interval's start to here.)
            emission * i.ds * exp(-extinction * d0)
        };
        if method != 3 {
            i.te += c;
            i.te2 += c * c;
        }
        i.samples += 1;
        (c, od)
    }

    /// What one light gives at a media sample `p` (POV-Ray's TestShadow): its colour, cone
    /// and fade, through the objects and media between (the shadow ray starts in `inside`),
    /// with the unit direction toward it; `None` where nothing arrives.
    fn media_light(
        &mut self,
        index: usize,
        p: DVec3,
        inside: &MediumStack,
    ) -> Option<(DVec3, Rgb)> {
        let scene = self.scene;
        let light = &scene.lights()[index];
        let (direction, distance) = super::lights::toward(light, p);
        let mut colour = light.colour * super::lights::attenuation(light, p, direction, distance);
        if colour.abs().max_element() < EPSILON {
            return None;
        }
        let mut shadow = Ray::new(p, direction);
        shadow.tmax = super::lights::reach(light, &shadow, distance)?;
        colour *= match &light.area {
            // An area light's grid, as from a surface (its shadow rays start in `inside`).
            Some(area) if area.size1 * area.size2 > 1 => {
                let was = std::mem::replace(&mut self.shadow_start, *inside);
                let start = ShadowStart::Medium(p);
                let seen = match self.light_stream {
                    Some(stream) => self.area_sampled(light, index, area, start, stream),
                    None => self.area_visibility((light, index), area, start),
                };
                self.shadow_start = was;
                seen
            }
            _ => {
                self.counts.shadow += 1;
                self.shadow_seen_from(&shadow, light, inside)
            }
        };
        (colour.abs().max_element() >= EPSILON).then_some((direction, colour))
    }

    /// Whether media may dim the shadow rays toward `light`: the scene holds interior media,
    /// or the light's shadow rays see the atmosphere (`media_attenuation`).
    pub(super) fn media_dims_shadows(&self, light: &Light) -> bool {
        self.scene.any_interior_media() || self.atmosphere_dims(light)
    }

    /// Whether the atmosphere or fog dims shadow rays toward `light`.
    fn atmosphere_dims(&self, light: &Light) -> bool {
        let scene = self.scene;
        light.media_interaction
            && light.media_attenuation
            && !(scene.atmosphere().is_empty() && scene.fogs().is_empty())
    }

    /// What reaches the end of a shadow ray toward `light` from the surface being shaded
    /// (the ray starts in the media the viewing ray was in).
    pub(super) fn shadow_seen(&mut self, ray: &Ray, light: &Light) -> Rgb {
        let inside = self.shadow_start;
        self.shadow_seen_from(ray, light, &inside)
    }

    /// What reaches the end of a shadow ray toward `light` that starts inside the media of
    /// `inside`: the surfaces' filters and fades ([`super::transmittance`]), and where the
    /// scene holds media, POV-Ray's media on shadow rays (`shadow_media`).
    fn shadow_seen_from(&mut self, ray: &Ray, light: &Light, inside: &MediumStack) -> Rgb {
        if !self.media_dims_shadows(light) {
            return super::transmittance(self.scene, ray);
        }
        let atmosphere = self.atmosphere_dims(light);
        super::shadow::transmittance_and(self.scene, ray, |crossings| {
            self.shadow_media(ray, inside, atmosphere, crossings)
        })
    }

    /// POV-Ray's media on a shadow ray: over each stretch up to a crossing, the media of the
    /// objects the ray is inside (when all are hollow), then, with `atmosphere`, the
    /// atmosphere and fog; the crossing then enters or leaves the object, POV-Ray's way
    /// (leaving the innermost, else entering). The rest of the ray, past the last
    /// crossing, sees the atmosphere only.
    fn shadow_media(
        &mut self,
        ray: &Ray,
        inside: &MediumStack,
        atmosphere: bool,
        crossings: &[ShadowCrossing],
    ) -> Rgb {
        let scene = self.scene;
        let length = ray.direction.length();
        let direction = ray.direction / length;
        let mut list = *inside;
        let mut through = Rgb::ONE;
        let mut last = 0.0;
        for c in crossings {
            let width = (c.t - last) * length;
            let origin = ray.origin + direction * (last * length);
            let hollow = list.hollow_space(scene);
            if hollow && !list.is_empty() {
                let pooled = self.pooled(&list, true);
                let list = MediaList::Gathered(&pooled);
                through = self.shadow_segment(list, origin, direction, width, through);
                self.give_pooled(pooled, true);
            }
            if atmosphere {
                through = self.shadow_atmosphere(origin, direction, width, through, hollow);
            }
            match list.position(scene, c.object) {
                Some(k) if !list.is_empty() => list.remove(k),
                _ => list.push(c.object),
            }
            last = c.t;
        }
        let rest = (ray.tmax - last) * length;
        if atmosphere && rest > SHADOW_TOLERANCE && list.hollow_space(scene) {
            let origin = ray.origin + direction * (last * length);
            through = self.shadow_atmosphere(origin, direction, rest, through, true);
        }
        through
    }

    /// `light` dimmed by `media` over a stretch of a shadow ray.
    fn shadow_segment(
        &mut self,
        media: MediaList<'_, 'a>,
        origin: DVec3,
        direction: DVec3,
        depth: f64,
        light: Rgb,
    ) -> Rgb {
        if media.len() == 0 || light.max_element() < EPSILON {
            return light;
        }
        let none = MediumStack::default();
        let seg = Segment {
            origin,
            direction,
            depth,
            shadow: true,
            inside: &none,
            hit: None,
        };
        self.through_media(media, &seg, light).0
    }

    /// `light` through the atmosphere and the fog (when `fog` and hollow) over a stretch of
    /// a shadow ray (fog only dims a shadow ray: POV-Ray adds no fog colour to it).
    fn shadow_atmosphere(
        &mut self,
        origin: DVec3,
        direction: DVec3,
        depth: f64,
        light: Rgb,
        fog: bool,
    ) -> Rgb {
        if light.max_element() < EPSILON {
            return light;
        }
        let scene = self.scene;
        let atmosphere = MediaList::Held(scene.atmosphere());
        let light = self.shadow_segment(atmosphere, origin, direction, depth, light);
        if fog && !scene.fogs().is_empty() {
            return light * fog_attenuation(scene, origin, direction, depth);
        }
        light
    }
}

/// The intervals a segment is sampled in (POV-Ray's ComputeMediaSampleInterval): at least
/// `intervals`, at least one per lit or unlit part, shared out by `ratio`; a single unlit
/// part of media without density is one interval whatever `intervals` says.
fn sample_intervals(lit: &[LitInterval], lead: &Media, out: &mut Vec<Interval>) {
    out.clear();
    let count = (lead.intervals as usize).max(lit.len());
    let interval = |lit: bool, s0: f64, ds: f64| Interval {
        lit,
        s0,
        ds,
        od: Rgb::ZERO,
        te: Rgb::ZERO,
        te2: Rgb::ZERO,
        samples: 0,
    };
    if let [only] = lit {
        if !only.lit && lead.constant() {
            out.push(interval(false, only.s0, only.s1 - only.s0));
        } else {
            let delta = (only.s1 - only.s0) / count as f64;
            for i in 0..count {
                out.push(interval(only.lit, only.s0 + delta * i as f64, delta));
            }
        }
    } else {
        let weight = |l: &LitInterval| if l.lit { lead.ratio } else { 1.0 - lead.ratio };
        let sum: f64 = lit.iter().map(weight).sum();
        let mut remaining = count;
        for (i, l) in lit.iter().enumerate() {
            // (At most what leaves one for each part after this one.)
            let share = ((weight(l) / sum * count as f64) as usize + 1)
                .min((remaining + i + 1).saturating_sub(lit.len()))
                .max(1);
            let delta = (l.s1 - l.s0) / share as f64;
            for j in 0..share {
                out.push(interval(l.lit, l.s0 + delta * j as f64, delta));
            }
            remaining -= share;
        }
    }
}

/// The roots of a t² + 2b t + c = 0 (discriminant `d` = b² − ac > 0), in order, with their
/// distances along the light's axis (k2 + t·k1); `None` when both lie behind the light.
fn roots_ahead(a: f64, b: f64, d: f64, k1: f64, k2: f64) -> Option<((f64, f64), (f64, f64))> {
    let d = d.sqrt();
    let (mut t1, mut t2) = ((-b + d) / a, (-b - d) / a);
    if t1 > t2 {
        std::mem::swap(&mut t1, &mut t2);
    }
    let (l1, l2) = (k2 + t1 * k1, k2 + t2 * k1);
    if l1 <= 0.0 && l2 <= 0.0 {
        return None;
    }
    Some(((t1, t2), (l1, l2)))
}

/// Where a ray meets a spotlight's falloff cone (apex `centre`, unit `axis`, cosine of the
/// falloff angle `cos_falloff`): POV-Ray's ComputeSpotLightInterval.
fn spot_part(seg: &Segment, centre: DVec3, axis: DVec3, cos_falloff: f64) -> Option<(f64, f64)> {
    let m = 1.0 / (cos_falloff * cos_falloff);
    let v = seg.origin - centre;
    let k1 = seg.direction.dot(axis);
    let k2 = v.dot(axis);
    let l = v.length();
    let in_cone = l > EPSILON && k2 / l >= cos_falloff;
    if k1 <= 0.0 && k2 < 0.0 {
        return None;
    }
    let k3 = v.dot(seg.direction);
    let k4 = v.dot(v);
    let a = 1.0 - k1 * k1 * m;
    let b = k3 - k1 * k2 * m;
    let c = k4 - k2 * k2 * m;
    if a == 0.0 {
        return in_cone.then(|| (0.0, -c / b));
    }
    let d = b * b - a * c;
    if d > EPSILON {
        let ((t1, t2), (l1, l2)) = roots_ahead(a, b, d, k1, k2)?;
        if l1 <= 0.0 {
            // (The first root is on the mirror cone.)
            if in_cone {
                return Some((0.0, if t2 > 0.0 { t2 } else { MAX_DISTANCE }));
            }
            return Some((t2, MAX_DISTANCE));
        }
        if l2 <= 0.0 {
            if in_cone {
                return Some((0.0, t1));
            }
            return Some((t1, MAX_DISTANCE));
        }
        Some((t1, t2))
    } else if d > -EPSILON {
        Some(if in_cone {
            (0.0, -b / a)
        } else {
            (-b / a, MAX_DISTANCE)
        })
    } else {
        None
    }
}

/// Where a ray meets a cylinder light's falloff cylinder (axis from `centre` along unit
/// `axis`, radius `falloff`), on the lit side of the light: POV-Ray's
/// ComputeCylinderLightInterval.
fn cylinder_part(seg: &Segment, centre: DVec3, axis: DVec3, falloff: f64) -> Option<(f64, f64)> {
    let v = seg.origin - centre;
    let k1 = seg.direction.dot(axis);
    let k2 = v.dot(axis);
    if k1 <= 0.0 && k2 < 0.0 {
        return None;
    }
    let a = 1.0 - k1 * k1;
    if a == 0.0 {
        return None;
    }
    let k3 = v.dot(seg.direction);
    let k4 = v.dot(v);
    let b = k3 - k1 * k2;
    let c = k4 - k2 * k2 - falloff * falloff;
    let d = b * b - a * c;
    if d <= EPSILON {
        return None;
    }
    let ((mut t1, mut t2), (l1, l2)) = roots_ahead(a, b, d, k1, k2)?;
    if l1 <= 0.0 {
        t1 = 0.0;
    } else if l2 <= 0.0 {
        t2 = (MAX_DISTANCE - k2) / k1;
    }
    Some((t1, t2))
}
