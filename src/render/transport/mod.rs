//! POV-Ray's shading model and Whitted recursion (pov-semantics §6–9): ambient, emission,
//! diffuse, phong, specular, metallic, reflection (plain and Fresnel), transmission through
//! filter and transmit, refraction with POV-Ray's interior bookkeeping (`medium`), interior
//! fade, fog (`fog`), rainbows (`rainbow`), media (`media`), lights and shadows (`lights`).

mod fog;
mod lights;
mod media;
mod medium;
pub(super) mod radiosity;
mod radiosity_legacy;
mod rainbow;
mod shadow;
mod spectrum;

use crate::geometry::Ray;
use crate::geometry::wide::PACKET;
use crate::scene::{
    Colour, Material, PatternSurface as Surface, Queries, Rgb, Scene, Seer, SurfaceHit,
    filter_colour,
};
use fog::{MISS_DEPTH, fogged};
use glam::{DMat3, DVec3};
use lights::LightSample;
pub(super) use medium::MediumStack;
use medium::{Refraction, SAME_IOR, interior_fade};
pub use shadow::transmittance;

/// POV-Ray's `MAX_DISTANCE`: hits farther along a ray than this are ignored.
const MAX_DISTANCE: f64 = 1e7;

/// Counts of rays traced, for statistics.
#[derive(Clone, Copy, Debug, Default)]
pub struct RayCounts {
    /// Camera rays.
    pub camera: u64,
    /// Reflected rays.
    pub reflected: u64,
    /// Refracted rays and rays continued through transparent surfaces.
    pub transmitted: u64,
    /// Shadow rays.
    pub shadow: u64,
    /// Secondary rays not traced because the ray was at `max_trace_level` (POV-Ray returns
    /// black for them: stacked glass turns dark).
    pub depth_limited: u64,
    /// Media intervals sampled (POV-Ray's `Media Intervals`).
    pub media_intervals: u64,
    /// Media samples taken (POV-Ray's `Media Samples`).
    pub media_samples: u64,
}

impl RayCounts {
    /// Adds another tally.
    pub fn add(&mut self, o: &RayCounts) {
        self.camera += o.camera;
        self.reflected += o.reflected;
        self.transmitted += o.transmitted;
        self.shadow += o.shadow;
        self.depth_limited += o.depth_limited;
        self.media_intervals += o.media_intervals;
        self.media_samples += o.media_samples;
    }

    /// Rays traced of every kind.
    pub fn total(&self) -> u64 {
        self.camera + self.reflected + self.transmitted + self.shadow
    }
}

/// Traces rays through one scene; holds the per-thread ray tally and scratch space.
pub struct Tracer<'a> {
    pub(super) scene: &'a Scene,
    /// Rays traced so far by this tracer.
    pub counts: RayCounts,
    /// Area-light visibility cache, reused between shading points.
    pub(super) area_cache: Vec<Option<Rgb>>,
    /// The grid points an area light traces at every shading point, with their cells.
    area_rays: Vec<(u32, Ray)>,
    /// The kind of the ray being traced, as far as objects hide from it (`no_image`,
    /// `no_reflection`, `no_radiosity`).
    seer: Seer,
    /// How much of the last ray traced saw the transparent background straight through
    /// (0 to 1): one minus its alpha (POV-Ray's transmit of the traced colour, +UA).
    pub see_through: f64,
    /// The camera sample being traced, as (pixel seed, sample number), when method 3 draws
    /// area-light positions from the pixel's sequence instead of POV-Ray's grid.
    pub(super) light_stream: Option<(u32, u32)>,
    /// The same for focal blur's lens points (method 3 with `sampled_blur`).
    pub(super) lens_stream: Option<(u32, u32)>,
    /// The objects that may block the shadow rays to the area light being sampled.
    pub(super) blockers: Vec<u32>,
    /// Each area light's pyramids found lately, with their possible blockers.
    hulls: Vec<lights::Hulls>,
    /// For each point light, the object that last blocked one of its shadow rays.
    shadow_cache: Vec<Option<u32>>,
    /// The object the last camera ray (level 1) hit, tested first by the next one.
    hint: Option<u32>,
    /// The media the ray being shaded is in: where its shadow rays start (POV-Ray's shadow
    /// rays copy the viewing ray's interior list).
    shadow_start: MediumStack,
    /// Lists reused by media.
    media_scratch: media::Scratch<'a>,
    /// The band of the spectrum the ray being traced carries, once a dispersing refraction
    /// has split it (POV-Ray's monochromatic rays): later dispersing surfaces bend it by its
    /// wavelength instead of splitting it again.
    band: Option<spectrum::Band>,
    /// `max_trace_level` and `adc_bailout` for the rays being traced: the scene's, or a
    /// radiosity sample's while it gathers.
    max_level: u32,
    bailout: f64,
    /// How far the last ray traced went before it met a surface (infinite if it met none).
    pub(super) distance: f64,
    /// Radiosity, if the scene has it: the cache and this tracer's part of the work.
    pub(super) gathering: Option<radiosity::Gathering<'a>>,
    /// A radiosity sample's ray's share of the sample (its index over the rays' count), while
    /// it is traced (negative otherwise): if it meets an object of lower `importance`, it
    /// goes no further. And the importance the last such ray found.
    pub(super) importance_query: f64,
    pub(super) importance_found: f64,
    /// During the pretrace: surfaces seen by rays other than radiosity's are not lit by the
    /// lights (their colour is not kept; only the light samples gather counts).
    pub(super) pretrace: bool,
}

/// Radiosity's light at a hit, shared by its layers: the unperturbed normal facing the ray,
/// the ray's weight, what the layers above the one being lit let through, and the light
/// gathered so far for the front and back sides.
struct Diffuse {
    raw: DVec3,
    weight: f64,
    filter: Rgb,
    front: Option<Rgb>,
    back: Option<Rgb>,
}

/// The pigment colour of `material` at `point` (a pattern of materials: its entries' colours
/// blended as their light is).
fn albedo(material: &Material, hit: &SurfaceHit, point: DVec3) -> Rgb {
    match &material.map {
        None => material.pigment.colour_on(point, &hit.surface).rgb,
        Some(map) => map.blend(point, &hit.surface, |entry, p| albedo(entry, hit, p)),
    }
}

/// grey(c) = 0.297 r + 0.589 g + 0.114 b (POV-Ray's luminance weights).
fn grey(c: Rgb) -> f64 {
    0.297 * c.x + 0.589 * c.y + 0.114 * c.z
}

/// POV-Ray's metallic factor `F` from the angle whose cosine is `cos`.
fn metallic_fresnel(cos: f64) -> f64 {
    let x = cos.clamp(-1.0, 1.0).acos() / std::f64::consts::FRAC_PI_2;
    (0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903).clamp(0.0, 1.0)
}

/// Fresnel reflectance for relative index `eta` (n_to / n_from) and incidence cosine `c`
/// (POV-Ray §7.5): 1 beyond the critical angle.
fn fresnel(eta: f64, c: f64) -> f64 {
    let g2 = eta * eta + c * c - 1.0;
    if g2 <= 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c);
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    (0.5 * a * a * (1.0 + b * b)).clamp(0.0, 1.0)
}

impl<'a> Tracer<'a> {
    /// A tracer over `scene`.
    pub fn new(scene: &'a Scene) -> Tracer<'a> {
        Tracer {
            scene,
            counts: RayCounts::default(),
            area_cache: Vec::new(),
            area_rays: Vec::new(),
            seer: Seer::default(),
            see_through: 0.0,
            light_stream: None,
            lens_stream: None,
            blockers: Vec::new(),
            hulls: Vec::new(),
            shadow_cache: Vec::new(),
            hint: None,
            shadow_start: MediumStack::default(),
            media_scratch: media::Scratch::default(),
            band: None,
            max_level: scene.max_trace_level(),
            bailout: scene.adc_bailout(),
            distance: f64::INFINITY,
            gathering: None,
            importance_query: -1.0,
            importance_found: 1.0,
            pretrace: false,
        }
    }

    /// The colour seen along `ray` (unit direction), which is inside `media`. `level` is the
    /// ray's trace level (a camera ray is 1) and `weight` its contribution to the pixel; rays
    /// past `max_trace_level` or below `adc_bailout` return black, as in POV-Ray.
    pub fn trace(&mut self, ray: &Ray, level: u32, weight: f64, media: &MediumStack) -> Rgb {
        if level > self.max_level || weight < self.bailout {
            self.see_through = 0.0;
            self.distance = f64::INFINITY;
            return Rgb::ZERO;
        }
        // POV-Ray ignores hits farther than MAX_DISTANCE (directions here are unit length).
        let mut ray = *ray;
        ray.tmax = ray.tmax.min(MAX_DISTANCE);
        let seer = self.seer;
        let hint = if level == 1 { self.hint } else { None };
        let hit = self.scene.nearest_hit(&ray, seer, hint);
        self.found(&ray, hit, level, weight, media)
    }

    /// [`Tracer::trace`] once the nearest hit along `ray` (its `tmax` cut to POV-Ray's
    /// farthest) is known.
    fn found(
        &mut self,
        ray: &Ray,
        hit: Option<crate::scene::Hit>,
        level: u32,
        weight: f64,
        media: &MediumStack,
    ) -> Rgb {
        if level == 1 {
            self.hint = hit.map(|h| h.object.0).or(self.hint);
        }
        let share = self.importance_query;
        if share >= 0.0 {
            // (POV-Ray's check on a radiosity sample's ray: an object of lower importance
            // than the ray's share stops it; only its distance counts.)
            let found = match hit {
                Some(h) => self.scene.object(h.object).importance(),
                None => self.scene.radiosity().map_or(1.0, |r| r.default_importance),
            };
            self.importance_found = found;
            if found < share {
                self.see_through = 0.0;
                self.distance = hit.map_or(f64::INFINITY, |h| h.t);
                return Rgb::ZERO;
            }
        }
        // The rays this one spawns are not checked, and the share is put back after, as
        // POV-Ray keeps it. (So, as in POV-Ray, once a sample has been gathered at a surface,
        // the rays its shading traces next, such as a reflection, carry the sample's last
        // share and stop at an object of lower importance.)
        self.importance_query = -1.0;
        let colour = self.traced(ray, hit, level, weight, media);
        self.importance_query = share;
        colour
    }

    /// [`Tracer::trace`] of camera rays (level 1, weight 1), up to eight neighbours (a
    /// packet), each inside its `media(ray)`: their nearest hits found together, then each
    /// ray shaded in order, `before(tracer, k)` called first (to set the pixel's sample
    /// streams) and its colour handed to `done(tracer, k, colour)` as soon as it is traced
    /// (so that `see_through` is the ray's). The colours are those of tracing them one by
    /// one.
    pub fn trace_camera_rays(
        &mut self,
        rays: &[Ray],
        media: impl Fn(&Ray) -> MediumStack,
        mut before: impl FnMut(&mut Self, usize),
        mut done: impl FnMut(&mut Self, usize, Rgb),
    ) {
        let (level, weight) = (1, 1.0);
        if level > self.max_level || weight < self.bailout {
            for (k, ray) in rays.iter().enumerate() {
                before(self, k);
                let colour = self.trace(ray, level, weight, &media(ray));
                done(self, k, colour);
            }
            return;
        }
        let mut packet = [Ray::new(DVec3::ZERO, DVec3::Z); PACKET];
        for (to, ray) in packet.iter_mut().zip(rays) {
            *to = *ray;
            to.tmax = to.tmax.min(MAX_DISTANCE);
        }
        let packet = &packet[..rays.len()];
        let mut hits = [None; PACKET];
        self.scene
            .nearest_hits(packet, self.seer, self.hint, &mut hits[..rays.len()]);
        for (k, (ray, &hit)) in packet.iter().zip(&hits).enumerate() {
            before(self, k);
            let colour = self.found(ray, hit, level, weight, &media(ray));
            done(self, k, colour);
        }
    }

    /// [`Tracer::trace`] past the checks: the colour of `ray`, which meets `hit` first.
    fn traced(
        &mut self,
        ray: &Ray,
        hit: Option<crate::scene::Hit>,
        level: u32,
        weight: f64,
        media: &MediumStack,
    ) -> Rgb {
        let ray = *ray;
        let seer = self.seer;
        let (mut colour, depth, hit) = match hit {
            None => {
                self.see_through = match self.scene.sky_sphere() {
                    None => 1.0 - self.scene.background_alpha(),
                    Some(_) => 0.0,
                };
                (self.escaped(ray.direction), MISS_DEPTH, None)
            }
            Some(hit) => {
                let surface = self.scene.surface(&ray, &hit);
                // (The rays this one spawns are not a radiosity sample's own.)
                self.seer = seer.transmitted();
                let colour = self.shade(&ray, hit.t, &surface, level, weight, media);
                self.seer = seer;
                (colour, hit.t, Some(hit.object))
            }
        };
        self.distance = if hit.is_some() { depth } else { f64::INFINITY };
        let scene = self.scene;
        let any_media = !scene.atmosphere().is_empty() || (hit.is_some() && !media.is_empty());
        let rainbows = scene.rainbows();
        // (Radiosity's rays see no media, fog or rainbow unless its `media` is on.)
        let volume = !seer.radiosity || scene.radiosity().is_some_and(|r| r.media);
        if (scene.fogs().is_empty() && rainbows.is_empty() && !any_media)
            || !media.hollow_space(scene)
            || !volume
        {
            return colour;
        }
        if !rainbows.is_empty() {
            let (c, transmit) = rainbow::rainbowed(rainbows, &ray, depth, colour);
            colour = c;
            self.see_through *= transmit;
        }
        if any_media {
            colour = self.seen_through_media(&ray, depth, hit, media, colour);
        }
        if scene.fogs().is_empty() {
            return colour;
        }
        fogged(scene, ray.origin, ray.direction, depth, colour)
    }

    /// `colour`, seen at distance `depth` along `ray` (in hollow space, ending on `hit`)
    /// through the media of the objects it is inside (when it ends on a surface), then the
    /// atmosphere (POV-Ray's order).
    fn seen_through_media(
        &mut self,
        ray: &Ray,
        depth: f64,
        hit: Option<crate::scene::ObjectId>,
        media: &MediumStack,
        mut colour: Rgb,
    ) -> Rgb {
        let scene = self.scene;
        let seg = media::Segment {
            origin: ray.origin,
            direction: ray.direction,
            depth,
            shadow: false,
            inside: media,
            hit,
        };
        if hit.is_some() && !media.is_empty() {
            let pooled = self.pooled(media, false);
            if !pooled.is_empty() {
                let (c, t) = self.through_media(media::MediaList::Gathered(&pooled), &seg, colour);
                colour = c;
                self.see_through *= grey(t);
            }
            self.give_pooled(pooled, false);
        }
        if !scene.atmosphere().is_empty() {
            let atmosphere = media::MediaList::Held(scene.atmosphere());
            let (c, t) = self.through_media(atmosphere, &seg, colour);
            colour = c;
            self.see_through *= grey(t);
        }
        colour
    }

    /// What a camera ray first meets, for AOV layers: its distance, the shading normal turned
    /// to face the ray, the surface's pigment colour (its top layer; a pattern of materials
    /// blended as it blends their light), and the object's number from 1 (all zero where the
    /// ray meets nothing; the distance is then infinite).
    pub fn first_hit(&mut self, ray: &Ray) -> (f64, DVec3, Rgb, u32) {
        let mut ray = *ray;
        ray.tmax = ray.tmax.min(MAX_DISTANCE);
        let Some(hit) = self.scene.nearest_hit(&ray, Seer::default(), None) else {
            return (f64::INFINITY, DVec3::ZERO, Rgb::ZERO, 0);
        };
        let surface = self.scene.surface(&ray, &hit);
        let n = if surface.normal.dot(ray.direction) > 0.0 {
            -surface.normal
        } else {
            surface.normal
        };
        let material = self.scene.material(surface.material);
        let albedo = albedo(material, &surface, surface.texture_point);
        (hit.t, n, albedo, surface.object.0 + 1)
    }

    /// [`Tracer::trace`] for a reflected ray.
    fn trace_reflected(&mut self, ray: &Ray, level: u32, weight: f64, media: &MediumStack) -> Rgb {
        let was = self.seer;
        self.seer = was.reflected();
        let colour = self.trace(ray, level, weight, media);
        self.seer = was;
        colour
    }

    /// The colour of a ray that hits nothing: the sky_sphere's layers over the background,
    /// top layer first, each seen through the ones above by their filter and transmit (POV-Ray's
    /// `ComputeSky`, with its rule for scenes before 3.7 too).
    fn escaped(&self, direction: DVec3) -> Rgb {
        let Some(sky) = &self.scene.sky_sphere() else {
            return self.scene.background();
        };
        let d = direction.normalize();
        let background = self.scene.background();
        let mut col = Rgb::ZERO;
        if self.scene.legacy_transparency() {
            // POV-Ray 3.6: the layers' filter and transmit multiply, channel by channel.
            let (mut through, mut filter, mut transmit, mut trans) = (Rgb::ONE, 1.0, 1.0, 1.0);
            for p in sky.pigments.iter().rev() {
                let c = p.colour_at(d);
                col += c.rgb * (trans * (1.0 - c.filter - c.transmit));
                through *= c.rgb;
                filter *= c.filter;
                transmit *= c.transmit;
                trans = f64::abs(filter) + f64::abs(transmit);
            }
            col * sky.emission + background * (through * filter + Rgb::splat(transmit))
        } else {
            let mut filter = Rgb::ONE;
            for p in sky.pigments.iter().rev() {
                let c = p.colour_at(d);
                col += c.rgb * (1.0 - c.filter - c.transmit) * filter * sky.emission;
                filter *= filter_colour(&c);
            }
            col + background * filter
        }
    }

    fn shade(
        &mut self,
        ray: &Ray,
        t: f64,
        hit: &SurfaceHit,
        level: u32,
        weight: f64,
        media: &MediumStack,
    ) -> Rgb {
        let material = self.scene.material(hit.material);
        // The normal slope and aoi patterns see: the surface's, until a layer's normal
        // perturbs it (POV-Ray's PNormal, below).
        let mut seen = hit.surface.normal;
        match &material.map {
            None => self.shade_layers(
                material,
                ray,
                t,
                hit,
                level,
                weight,
                media,
                (&mut seen, None),
            ),
            Some(_) => self.shade_mapped(
                material,
                ray,
                t,
                hit,
                level,
                weight,
                media,
                (&mut seen, None),
            ),
        }
    }

    /// A pattern of materials: the one (or the blend of the two) its value picks, each lit on
    /// its own (POV-Ray's texture maps).
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn shade_mapped(
        &mut self,
        material: &'a Material,
        ray: &Ray,
        t: f64,
        hit: &SurfaceHit,
        level: u32,
        weight: f64,
        media: &MediumStack,
        (seen, warp): (&mut DVec3, Option<&'a DMat3>),
    ) -> Rgb {
        let Some(map) = &material.map else {
            return self.shade_layers(material, ray, t, hit, level, weight, media, (seen, warp));
        };
        let surface = Surface {
            normal: *seen,
            ..hit.surface
        };
        // The entries' normals are seen in this pattern's space (POV-Ray's list of warps).
        let warp = map.normal_to_pattern().or(warp);
        map.blend(hit.texture_point, &surface, |entry, texture_point| {
            let hit = &SurfaceHit {
                texture_point,
                ..*hit
            };
            self.shade_mapped(entry, ray, t, hit, level, weight, media, (&mut *seen, warp))
        })
    }

    /// The light leaving the surface hit, of `material` (not a pattern of materials): its
    /// layers' light, then what passes through them and what they reflect.
    ///
    /// `seen` is the normal slope and aoi patterns see (POV-Ray's PNormal): each layer whose
    /// normal is perturbed leaves its normal there, as seen in `warp`'s space (the pattern
    /// space of the innermost pattern of materials around), for its own pigment and for
    /// every pattern evaluated after it on this hit.
    #[allow(clippy::too_many_arguments)]
    fn shade_layers(
        &mut self,
        material: &'a Material,
        ray: &Ray,
        t: f64,
        hit: &SurfaceHit,
        level: u32,
        weight: f64,
        media: &MediumStack,
        (seen, warp): (&mut DVec3, Option<&DMat3>),
    ) -> Rgb {
        let scene = self.scene;
        self.shadow_start = *media;
        let d = ray.direction;
        // Shade the side facing the ray (decided by the shading normal, as POV-Ray decides it:
        // a smooth triangle seen at a grazing angle may face away by its smooth normal).
        let facing = if hit.normal.dot(d) > 0.0 { -1.0 } else { 1.0 };
        let raw = hit.normal * facing;

        // Relative indices for this crossing (POV-Ray §9.1).
        let object = scene.object(hit.object);
        let refraction = Refraction::new(scene, media, hit.object);
        let interior = scene.interior(object);
        // (POV-Ray's old `refraction` multiplies whatever passes through, inside or not.)
        let fade = if refraction.inside && interior.fade_distance.abs() > 1e-10 {
            interior_fade(interior, t * d.length()) * interior.refraction
        } else {
            Rgb::splat(interior.refraction)
        };

        // Each layer (top first) adds its light as seen through the layers above it, `filter`
        // (POV-Ray's ComputeLightedTexture); a texture has one layer unless layered.
        let (n, colour, top_reflec) =
            self.layer_at(material, hit, d, raw, refraction.fresnel_eta, (seen, warp));
        let top_colour = colour;
        // (What the lower layers saw, replayed for their reflections below.)
        let mut replay = *seen;
        // (Radiosity's light at the hit, gathered once for all layers, front and back.)
        let mut diffuse = Diffuse {
            raw,
            weight,
            filter: Rgb::ONE,
            front: None,
            back: None,
        };
        let mut result = self.layer_light(material, &colour, n, ray, hit, &mut diffuse);
        let mut filter = filter_colour(&colour);
        if material.finish.conserve_energy {
            filter *= (Rgb::ONE - top_reflec).min(Rgb::ONE);
        }
        let mut layers = 1;
        for layer in material.under.iter().rev() {
            if grey(filter).abs().min(1.0) <= self.bailout {
                break;
            }
            layers += 1;
            let (n_l, colour, reflec) = self.layer_at(
                layer,
                hit,
                d,
                raw,
                refraction.fresnel_eta,
                (&mut *seen, warp),
            );
            diffuse.filter = filter;
            result += self.layer_light(layer, &colour, n_l, ray, hit, &mut diffuse) * filter;
            filter *= filter_colour(&colour);
            if layer.finish.conserve_energy {
                filter *= (Rgb::ONE - reflec).min(Rgb::ONE);
            }
        }
        let cos_i = -d.dot(n);

        // Transmission through all the layers: straight on through ior-1 surfaces (same trace
        // level), refracted otherwise (by the top layer's normal); no secondary ray leaves a
        // ray already at max_trace_level.
        let mut total_internal_reflection = false;
        // (What of the background shows through, by the layers' filter.)
        let mut see_through = 0.0;
        let wants_transmission = filter != Rgb::ZERO && grey(filter).abs().min(1.0) > self.bailout;
        if wants_transmission && level >= self.max_level {
            self.counts.depth_limited += 1;
        }
        if wants_transmission && level < self.max_level {
            let w = weight * filter.abs().max_element();
            let mut eta = refraction.refraction_eta;
            let disperses = (refraction.dispersion - 1.0).abs() >= SAME_IOR;
            if disperses {
                if let Some(band) = self.band {
                    // (A ray of one wavelength bends by that wavelength's index.)
                    eta = band.ior(eta, refraction.dispersion);
                }
            }
            if disperses && self.band.is_none() {
                // Dispersion: one ray per band, each refracted (or totally reflected) by its
                // own index and weighted by its hue; their mean is filtered as one refracted
                // ray (with no transmit left for the alpha channel, as in POV-Ray).
                let mut sum = Rgb::ZERO;
                for i in 0..refraction.bands {
                    let band = spectrum::Band::new(i, refraction.bands);
                    self.band = Some(band);
                    let eta = band.ior(eta, refraction.dispersion);
                    let c = match refracted(d, n, cos_i, eta) {
                        Some(dir) => {
                            let refracted = scene.spawn(hit, ray.origin, dir);
                            self.counts.transmitted += 1;
                            self.trace(&refracted, level + 1, w, &refraction.after)
                        }
                        None => {
                            let mirror = scene.spawn(hit, ray.origin, mirror_direction(d, n, raw));
                            self.counts.reflected += 1;
                            let seen = self.trace_reflected(&mirror, level + 1, w, media);
                            seen * self.irid(material, &mirror, d, n, hit)
                        }
                    };
                    sum += c * band.hue();
                }
                self.band = None;
                result += fade * (sum / f64::from(refraction.bands)) * filter;
            } else if (eta - 1.0).abs() < SAME_IOR && !disperses {
                let through = scene.spawn(hit, ray.origin, d);
                self.counts.transmitted += 1;
                result += fade * self.trace(&through, level, w, &refraction.after) * filter;
                see_through = self.see_through * grey(filter);
            } else {
                if let Some(dir) = refracted(d, n, cos_i, eta) {
                    let refracted = scene.spawn(hit, ray.origin, dir);
                    self.counts.transmitted += 1;
                    result +=
                        fade * self.trace(&refracted, level + 1, w, &refraction.after) * filter;
                    see_through = self.see_through * grey(filter);
                } else {
                    // Total internal reflection: the mirror ray at full weight, instead of the
                    // surface's own reflection.
                    total_internal_reflection = true;
                    let mirror = scene.spawn(hit, ray.origin, mirror_direction(d, n, raw));
                    self.counts.reflected += 1;
                    let seen = self.trace_reflected(&mirror, level + 1, weight, media);
                    result += fade * seen * self.irid(material, &mirror, d, n, hit);
                }
            }
        }

        // Mirror reflection of each layer, weighted by what the layers above let through
        // (after total internal reflection, only layers whose normal differs from the top's).
        let ctx = (ray, hit, raw, level, media);
        if !total_internal_reflection {
            result += self.mirror(material, n, top_reflec, weight, ctx);
        }
        if layers > 1 {
            let mut above = Rgb::ONE;
            let mut previous = (material, top_reflec, top_colour);
            for layer in material.layers().take(layers).skip(1) {
                // (What the layer above lets through.)
                let (upper, upper_reflec, upper_colour) = previous;
                above *= filter_colour(&upper_colour);
                if upper.finish.conserve_energy {
                    above *= (Rgb::ONE - upper_reflec).min(Rgb::ONE);
                }
                let (n_l, colour, reflec) = self.layer_at(
                    layer,
                    hit,
                    d,
                    raw,
                    refraction.fresnel_eta,
                    (&mut replay, warp),
                );
                previous = (layer, reflec, colour);
                let same_normal = (n_l - n).abs().max_element() <= 1e-10;
                if total_internal_reflection && same_normal {
                    continue;
                }
                let w = weight * grey(above).abs().min(1.0);
                result += self.mirror(layer, n_l, reflec, w, ctx);
            }
        }
        self.see_through = see_through.clamp(0.0, 1.0);
        result
    }

    /// One layer's ambient (or radiosity's light), emission and direct light, for its colour
    /// and shading normal.
    #[inline]
    fn layer_light(
        &mut self,
        layer: &Material,
        colour: &Colour,
        n: DVec3,
        ray: &Ray,
        hit: &SurfaceHit,
        diffuse: &mut Diffuse,
    ) -> Rgb {
        let scene = self.scene;
        let pigment = colour.rgb;
        let att = if scene.legacy_transparency() {
            1.0 - (colour.filter * pigment.max_element() + colour.transmit)
        } else {
            1.0 - colour.filter - colour.transmit
        };
        let finish = &layer.finish;
        let mut lit = pigment * finish.emission * att;
        match scene.radiosity() {
            Some(r) => {
                // POV-Ray 3.7 drops `ambient` once radiosity is on (not for older scenes).
                if r.keeps_ambient {
                    lit += pigment * finish.ambient * scene.ambient_light() * att;
                }
                lit += self.radiosity_light(pigment, finish, att, n, hit, diffuse);
            }
            None => lit += pigment * finish.ambient * scene.ambient_light() * att,
        }
        if self.pretrace && !self.seer.radiosity {
            return lit;
        }
        let object = scene.object(hit.object);
        let double = object.sight().double_illuminate;
        for index in 0..scene.lights().len() {
            if !object.lit_by(&scene.lights()[index]) {
                continue;
            }
            let Some(sample) = self.light_sample(
                index,
                hit,
                ray.origin,
                n,
                finish.diffuse_back > 0.0 || double,
            ) else {
                continue;
            };
            // `crand`: the diffuse intensity less a random fraction (a hash of the point and
            // the light, so the same for any thread count).
            let grain = if finish.crand > 0.0 {
                finish.crand * grain(hit.point, index)
            } else {
                0.0
            };
            let mut light = self.lit(layer, colour, att, ray.direction, n, &sample, grain, double);
            if finish.irid.amount > 0.0 {
                light *= scene.irid(finish, sample.direction, ray.direction, n, hit.point);
            }
            lit += light;
        }
        lit
    }

    /// Radiosity's light on one layer (POV-Ray's ComputeLightedTexture): the light other
    /// surfaces send the hit, gathered at the first layer that could show enough of it (by
    /// its diffuse, colour and what the layers above let through) and reused by the layers
    /// under it; the back side's likewise for a `diffuse_back` finish. Nothing at the last
    /// bounce.
    fn radiosity_light(
        &mut self,
        pigment: Rgb,
        finish: &crate::scene::Finish,
        att: f64,
        n: DVec3,
        hit: &SurfaceHit,
        d: &mut Diffuse,
    ) -> Rgb {
        let Some(g) = &self.gathering else {
            return Rgb::ZERO;
        };
        let Some(r) = self.scene.radiosity() else {
            return Rgb::ZERO;
        };
        if g.depth >= r.recursion_limit {
            return Rgb::ZERO;
        }
        let most = grey(d.filter * pigment) * att;
        if d.front.is_none() && most * finish.diffuse > self.bailout {
            d.front = Some(self.ambient(hit, d.raw, n, d.weight * most * finish.diffuse));
        }
        let mut light = pigment * d.front.unwrap_or(Rgb::ZERO) * (att * finish.diffuse);
        if finish.diffuse_back != 0.0 {
            if d.back.is_none() && most * finish.diffuse_back > self.bailout {
                let w = d.weight * most * finish.diffuse_back;
                d.back = Some(self.ambient(hit, -d.raw, -n, w));
            }
            light += pigment * d.back.unwrap_or(Rgb::ZERO) * (att * finish.diffuse_back);
        }
        light
    }

    /// The mirror reflection of one layer with shading normal `n` and reflectivity `reflec`,
    /// traced at `weight` (times POV-Ray's bound on the reflectivity).
    fn mirror(
        &mut self,
        layer: &Material,
        n: DVec3,
        reflec: Rgb,
        weight: f64,
        (ray, hit, raw, level, media): (&Ray, &SurfaceHit, DVec3, u32, &MediumStack),
    ) -> Rgb {
        if reflec.max_element() <= 0.0 {
            return Rgb::ZERO;
        }
        let scene = self.scene;
        if level >= self.max_level {
            self.counts.depth_limited += 1;
            return Rgb::ZERO;
        }
        let reflected = scene.spawn(hit, ray.origin, mirror_direction(ray.direction, n, raw));
        self.counts.reflected += 1;
        // POV-Ray weighs a plain reflection by its largest possible value (max of min and
        // max), whatever the angle; only Fresnel reflection uses the actual reflectivity.
        let rf = &layer.finish.reflection;
        let bound = if rf.fresnel {
            reflec.max_element()
        } else {
            rf.max.max_element().max(rf.min.max_element())
        };
        let mut seen = self.trace_reflected(&reflected, level + 1, weight * bound, media);
        seen *= self.irid(layer, &reflected, ray.direction, n, hit);
        if rf.exponent != 1.0 {
            seen = seen.max(DVec3::ZERO).powf(1.0 / rf.exponent);
        }
        reflec * seen
    }

    /// The tint a layer's `irid` gives light reflected into `mirror` (any mirror ray, totally
    /// internally reflected ones included, as POV-Ray's ComputeReflection applies it); white
    /// without irid.
    #[inline]
    fn irid(&self, layer: &Material, mirror: &Ray, d: DVec3, n: DVec3, hit: &SurfaceHit) -> Rgb {
        if layer.finish.irid.amount > 0.0 {
            let to = mirror.direction.normalize();
            self.scene.irid(&layer.finish, to, d, n, hit.point)
        } else {
            Rgb::ONE
        }
    }

    /// One layer at the hit: its shading normal (perturbed if the layer has a normal), its
    /// colour and its reflectivity. A perturbed normal is left in `seen` before the colour
    /// is found, as POV-Ray's Perturb_Normal leaves it in the intersection's PNormal, seen
    /// in the space `warp` takes world normals to, if given.
    #[inline]
    fn layer_at(
        &self,
        layer: &Material,
        hit: &SurfaceHit,
        d: DVec3,
        raw: DVec3,
        fresnel_eta: f64,
        (seen, warp): (&mut DVec3, Option<&DMat3>),
    ) -> (DVec3, Colour, Rgb) {
        let mut surface = Surface {
            normal: *seen,
            ..hit.surface
        };
        let n = match &layer.normal {
            None => raw,
            Some(normal) => {
                let n = normal.perturb_on(hit.texture_point, raw, &surface);
                *seen = warp.map_or(n, |m| *m * n).normalize();
                surface.normal = *seen;
                n
            }
        };
        let colour = layer.pigment.colour_on(hit.texture_point, &surface);
        let reflec = reflectivity(layer, &colour, -d.dot(n), fresnel_eta);
        (n, colour, reflec)
    }

    /// Diffuse, phong and specular from one light sample (§7.3).
    /// The light of one light sample on a layer; `grain` is subtracted from the diffuse
    /// intensity (`crand`).
    #[allow(clippy::too_many_arguments)]
    fn lit(
        &self,
        material: &Material,
        colour: &Colour,
        att: f64,
        d: DVec3,
        n: DVec3,
        s: &LightSample,
        grain: f64,
        double: bool,
    ) -> Rgb {
        let finish = &material.finish;
        let pigment = colour.rgb;
        let lc = s.colour;
        let mut result = Rgb::ZERO;
        let cos_nl = n.dot(s.direction);
        if cos_nl >= 0.0 || double {
            // (`double_illuminate`: a light behind lights the surface as one in front.)
            if finish.diffuse > 0.0 {
                let intensity = finish.diffuse * att * brilliance(cos_nl.abs(), finish.brilliance);
                result += pigment * lc * (intensity - grain);
            }
        } else if finish.diffuse_back > 0.0 {
            // A light behind the surface lights it through, with the back-side diffuse.
            let intensity = finish.diffuse_back * att * brilliance(-cos_nl, finish.brilliance);
            result += pigment * lc * (intensity - grain);
        }
        if s.highlights && cos_nl > 0.0 && (finish.phong > 0.0 || finish.specular > 0.0) {
            let lc_metal = if finish.metallic != 0.0 {
                let f = metallic_fresnel(cos_nl);
                lc * (Rgb::ONE + finish.metallic * (1.0 - f) * (pigment - Rgb::ONE))
            } else {
                lc
            };
            if finish.phong > 0.0 {
                // Phong: the mirrored view ray against the light direction.
                let r = d - 2.0 * d.dot(n) * n;
                let c = r.dot(s.direction);
                if c > 0.0 {
                    result += finish.phong * c.powf(finish.phong_size) * lc_metal;
                }
            }
            if finish.specular > 0.0 {
                // Blinn: the half vector against the normal.
                let h = (s.direction - d).normalize_or_zero();
                let c = n.dot(h);
                if c > 0.0 {
                    result += finish.specular * c.powf(1.0 / finish.roughness) * lc_metal;
                }
            }
        }
        result
    }
}

/// A number in [0, 1) for `crand`, from the bits of the point and the light's index.
/// The direction of a ray of unit direction `d` refracted by the relative index `eta` at a
/// surface of normal `n` (facing the ray, `cos_i` = −d·n), by Heckbert's method; `None` under
/// total internal reflection.
fn refracted(d: DVec3, n: DVec3, cos_i: f64, eta: f64) -> Option<DVec3> {
    let k = 1.0 + eta * eta * (cos_i * cos_i - 1.0);
    (k >= 0.0).then(|| (eta * d + (eta * cos_i - k.sqrt()) * n).normalize())
}

fn grain(p: DVec3, light: usize) -> f64 {
    let mut h = (light as u64).wrapping_add(0x9E37_79B9_7F4A_7C15);
    for v in [p.x, p.y, p.z] {
        h = (h ^ v.to_bits()).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        h ^= h >> 31;
    }
    (h >> 11) as f64 / (1u64 << 53) as f64
}

/// POV-Ray's reflectivity for incidence cosine `cos_i` (§7.5); `eta` is the relative index
/// the Fresnel term uses.
fn reflectivity(material: &Material, colour: &Colour, cos_i: f64, eta: f64) -> Rgb {
    let r = &material.finish.reflection;
    if !r.is_some() {
        return Rgb::ZERO;
    }
    let mut reflec = if r.fresnel {
        let f = fresnel(eta, cos_i);
        f * r.max + (1.0 - f) * r.min
    } else {
        let frac = (1.0 - cos_i).max(0.0).powf(r.falloff);
        frac * r.max + (1.0 - frac) * r.min
    };
    if r.metallic != 0.0 {
        let f = metallic_fresnel(cos_i);
        reflec *= Rgb::ONE + r.metallic * (1.0 - f) * (colour.rgb - Rgb::ONE);
    }
    reflec
}

/// `cos^brilliance`; brilliance 1 (the default) skips the `pow`, which gives the same value.
/// A light grazing the surface (`cos` 0) gives nothing, whatever the exponent: a negative
/// brilliance would make it infinite.
fn brilliance(cos: f64, exponent: f64) -> f64 {
    if exponent == 1.0 {
        cos
    } else if cos > 0.0 {
        cos.powf(exponent)
    } else {
        0.0
    }
}

/// The mirror direction of `d` about the shading normal `n` (perturbed, facing the ray), as
/// POV-Ray makes it: a direction that the perturbation would send into the surface (behind the
/// unperturbed normal `raw`) is reflected about `raw` instead, or folded back out.
fn mirror_direction(d: DVec3, n: DVec3, raw: DVec3) -> DVec3 {
    let mut r = d + (-2.0 * d.dot(n)) * n;
    let behind = r.dot(raw);
    if behind < 0.0 {
        if r.dot(n) < 0.0 {
            r = d + (-2.0 * d.dot(raw)) * raw;
        } else {
            r += (-2.0 * behind) * raw;
        }
    }
    r.normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grazing_light_gives_nothing_at_any_brilliance() {
        for exponent in [-3.0, -1.0, 0.0, 0.5, 1.0, 10.0] {
            assert_eq!(brilliance(0.0, exponent), 0.0, "{exponent}");
            assert!(brilliance(0.5, exponent).is_finite());
        }
        assert_eq!(brilliance(0.5, -1.0), 2.0);
    }

    #[test]
    fn metallic_fresnel_matches_povray_table() {
        // x = 0 (normal incidence): 0.014567225/1.2544 − 0.011612903 ≈ 0.
        assert!(metallic_fresnel(1.0).abs() < 1e-6);
        // Grazing (x = 1): 0.014567225/0.0144 − 0.011612903 ≈ 1.0 (clamped).
        assert!((metallic_fresnel(0.0) - 1.0).abs() < 1e-6);
    }

    /// `crand`'s numbers are uniform in [0, 1) like POV-Ray's (its mean darkening is
    /// `crand / 2`), differ between neighbouring points and lights, and repeat for a point.
    #[test]
    fn crand_grain_is_uniform_and_repeatable() {
        let (mut sum, mut below_tenth, n) = (0.0, 0, 20_000);
        for i in 0..n {
            let p = DVec3::new(i as f64 * 1e-3, 0.5, -2.0);
            let g = grain(p, i % 3);
            assert!((0.0..1.0).contains(&g));
            assert_eq!(g, grain(p, i % 3));
            sum += g;
            below_tenth += usize::from(g < 0.1);
        }
        assert!((sum / n as f64 - 0.5).abs() < 0.01, "{}", sum / n as f64);
        assert!((below_tenth as f64 / n as f64 - 0.1).abs() < 0.01);
        assert_ne!(grain(DVec3::ONE, 0), grain(DVec3::ONE, 1));
    }

    #[test]
    fn grey_uses_povray_weights() {
        assert!((grey(Rgb::ONE) - 1.0).abs() < 1e-12);
        assert_eq!(grey(Rgb::X), 0.297);
    }

    #[test]
    fn fresnel_of_glass_at_normal_incidence_is_four_percent() {
        assert!((fresnel(1.5, 1.0) - 0.04).abs() < 1e-12);
        assert_eq!(fresnel(1.0, 0.7), 0.0);
        // Leaving glass beyond the critical angle: total reflection.
        assert_eq!(fresnel(1.0 / 1.5, 0.3), 1.0);
    }
}
