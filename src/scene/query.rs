//! Ray queries on the built scene: the nearest hit through the index, the surface at a hit,
//! what reaches a light through transparent objects, inside tests.

use super::*;
use crate::geometry::wide::{PACKET, bits};

impl Scene {
    /// The interior of `object`.
    pub fn interior(&self, object: &Object) -> &Interior {
        &self.interiors[object.interior as usize]
    }

    /// The object with id `id`.
    pub fn object(&self, id: ObjectId) -> &Object {
        &self.objects[id.0 as usize]
    }

    /// The material with id `id`.
    pub fn material(&self, id: MaterialId) -> &Material {
        &self.materials[id.0 as usize]
    }

    /// Crossings of a world ray with one object (object space when transformed; `t` is the
    /// same in both spaces because the direction is not renormalised).
    fn crossings(object: &Object, ray: &Ray) -> Crossings {
        if !object.admits(ray) {
            return Crossings::NONE;
        }
        match &object.transform {
            None => object.shape.intersect(ray),
            Some(t) => object
                .shape
                .intersect(&ray.transformed(&t.object_from_world)),
        }
    }

    /// The nearest hit along `ray`, of any object (whatever it hides from: the probe's and
    /// the tests' question).
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        self.nearest(ray, None, None)
    }

    /// Offers object `i` to a ray whose nearest hit so far is `best`: if the ray meets it
    /// nearer (or at a tie the object wins), `best` becomes that hit and the distance the
    /// ray need look no farther than is returned.
    ///
    /// Two hits within rounding of each other (a glass box standing on the floor plane: the
    /// ray leaves the glass where it meets the floor) are one point, and the object first in
    /// POV-Ray's test order is hit, as in POV-Ray, whose depths there are exactly equal;
    /// rounding would otherwise pick either at random from pixel to pixel. So each hit
    /// leaves room for a tie just beyond it. (Which hit wins depends not on the order the
    /// objects are offered in.)
    #[inline(always)]
    fn offer(&self, i: u32, ray: &Ray, seer: Option<Seer>, best: &mut Option<Hit>) -> Option<f64> {
        let object = &self.objects[i as usize];
        if seer.is_some_and(|s| !object.seen_by(s)) {
            return None;
        }
        // (A sphere in world space that admits every ray turns most of the rays that miss it
        // away here, before the full test.)
        let plain = object.transform.is_none() && object.extra.is_none();
        if plain && object.shape.clearly_missed(ray) {
            return None;
        }
        self.offer_crossings(i, ray, Self::crossings(object, ray), best)
    }

    /// [`Scene::offer`] once object `i`'s crossings along the ray are known.
    #[inline(always)]
    fn offer_crossings(
        &self,
        i: u32,
        ray: &Ray,
        crossings: Crossings,
        best: &mut Option<Hit>,
    ) -> Option<f64> {
        let (t, part) = crossings.first_part()?;
        if let Some(b) = best {
            let tied = (t - b.t).abs() <= TIE * b.t.abs();
            if tied && !self.wins_tie(i, b.object.0, ray) {
                return None;
            }
        }
        *best = Some(Hit {
            t,
            object: ObjectId(i),
            part,
        });
        Some(t + TIE * t.abs())
    }

    /// The nearest hit along `ray` of the objects `seer` sees (all with `None`); object
    /// `hint` (the last camera ray's) is tested first, which changes no answer.
    #[inline]
    fn nearest(&self, ray: &Ray, seer: Option<Seer>, hint: Option<u32>) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut ray = *ray;
        let mut test = |i: u32, ray: &Ray| self.offer(i, ray, seer, &mut best);
        if let Some(h) = hint {
            if let Some(t) = test(h, &ray) {
                ray.tmax = t;
            }
        }
        match &self.index {
            Some(index) => {
                for &i in &index.unbounded {
                    if Some(i) != hint {
                        if let Some(t) = test(i, &ray) {
                            ray.tmax = t;
                        }
                    }
                }
                index.closest(&ray, |i, tmax| {
                    if Some(i) == hint {
                        return None;
                    }
                    test(i, &Ray { tmax, ..ray })
                });
            }
            None => {
                let inv = ray.direction.recip();
                for (i, &bounds) in self.scan_bounds.iter().enumerate() {
                    if Some(i as u32) != hint && may_hit(bounds, &ray, inv) {
                        if let Some(t) = test(i as u32, &ray) {
                            ray.tmax = t;
                        }
                    }
                }
            }
        }
        best
    }

    /// [`Scene::nearest`] for each of `rays` (at most [`PACKET`]), into `hits`: with an
    /// index, its tree walked once for all of them.
    fn nearest_packet(
        &self,
        rays: &[Ray],
        seer: Option<Seer>,
        hint: Option<u32>,
        hits: &mut [Option<Hit>],
    ) {
        let all = (1 << rays.len()) - 1;
        let mut tmax = [f64::INFINITY; PACKET];
        for (k, (ray, best)) in rays.iter().zip(hits.iter_mut()).enumerate() {
            *best = None;
            tmax[k] = ray.tmax;
        }
        if let Some(h) = hint {
            self.offer_packet(h, all, rays, seer, hits, &mut tmax);
        }
        let Some(index) = &self.index else {
            let inverse: [DVec3; PACKET] =
                std::array::from_fn(|k| rays[k.min(rays.len() - 1)].direction.recip());
            for (i, &bounds) in self.scan_bounds.iter().enumerate() {
                if Some(i as u32) == hint {
                    continue;
                }
                let mut rays_in = 0;
                for (k, ray) in rays.iter().enumerate() {
                    let ray = Ray {
                        tmax: tmax[k],
                        ..*ray
                    };
                    if may_hit(bounds, &ray, inverse[k]) {
                        rays_in |= 1 << k;
                    }
                }
                self.offer_packet(i as u32, rays_in, rays, seer, hits, &mut tmax);
            }
            return;
        };
        for &i in &index.unbounded {
            if Some(i) != hint {
                self.offer_packet(i, all, rays, seer, hits, &mut tmax);
            }
        }
        index.closest_packet(rays, &tmax, |rays_in, i, tmax| {
            if Some(i) != hint {
                self.offer_packet(i, rays_in, rays, seer, hits, tmax);
            }
        });
    }

    /// [`Scene::offer`] of object `i` to the rays of mask `rays_in` (ray `k` is bit `k`),
    /// ray `k`'s nearest hit so far being `best[k]`, at `tmax[k]`, which it lowers where it
    /// meets the object nearer: a mesh met by several rays is walked once for them all.
    fn offer_packet(
        &self,
        i: u32,
        rays_in: u32,
        rays: &[Ray],
        seer: Option<Seer>,
        best: &mut [Option<Hit>],
        tmax: &mut [f64; PACKET],
    ) {
        let object = &self.objects[i as usize];
        if !matches!(object.shape, Shape::Mesh(_)) || rays_in.count_ones() < 2 {
            for k in bits(rays_in) {
                let ray = Ray {
                    tmax: tmax[k],
                    ..rays[k]
                };
                if let Some(t) = self.offer(i, &ray, seer, &mut best[k]) {
                    tmax[k] = t;
                }
            }
            return;
        }
        if seer.is_some_and(|s| !object.seen_by(s)) {
            return;
        }
        // The rays the object admits, in its own space (as `Scene::crossings` takes them).
        let mut local = [rays[0]; PACKET];
        let mut which = [0; PACKET];
        let mut n = 0;
        for k in bits(rays_in) {
            let ray = Ray {
                tmax: tmax[k],
                ..rays[k]
            };
            if object.admits(&ray) {
                local[n] = match &object.transform {
                    None => ray,
                    Some(t) => ray.transformed(&t.object_from_world),
                };
                which[n] = k;
                n += 1;
            }
        }
        let mut crossings = [Crossings::NONE; PACKET];
        object
            .shape
            .intersect_packet(&local[..n], &mut crossings[..n]);
        for (&k, crossings) in which[..n].iter().zip(crossings) {
            let ray = Ray {
                tmax: tmax[k],
                ..rays[k]
            };
            if let Some(t) = self.offer_crossings(i, &ray, crossings, &mut best[k]) {
                tmax[k] = t;
            }
        }
    }

    /// Whether object `new`, hit at the same depth as object `old`, is the one POV-Ray sees:
    /// the first it tests. With its bounding tree on, POV-Ray tests objects as the ray enters
    /// their boxes (a priority queue by entry depth), so of two objects standing alone the
    /// one whose box the ray enters first wins (two coplanar box faces: the box that reaches
    /// nearer the camera); otherwise, and within a union, the fixed test order of `rank`.
    fn wins_tie(&self, new: u32, old: u32, ray: &Ray) -> bool {
        let (a, b) = (&self.objects[new as usize], &self.objects[old as usize]);
        if self.bounded_last && a.bounded && b.bounded && self.alone(new) && self.alone(old) {
            if let (Some(ba), Some(bb)) = (a.world_bounds(), b.world_bounds()) {
                let (ea, eb) = (entry_depth(ba, ray), entry_depth(bb, ray));
                if (ea - eb).abs() > 1e-9 * ea.abs().max(eb.abs()) {
                    return ea < eb;
                }
            }
        }
        a.rank <= b.rank
    }

    /// Whether object `i` stands alone (is no member of a union).
    fn alone(&self, i: u32) -> bool {
        let base = |k: usize| self.objects.get(k).map(|o| o.rank >> 32);
        let i = i as usize;
        let own = base(i);
        (i == 0 || base(i - 1) != own) && base(i + 1) != own
    }

    /// `f` of `ray` in the space of `object` (the ray itself, not a copy, for an object
    /// without a transformation: a copy just written and read at once stalled the plane
    /// test of `glass.rt`'s shadow rays on forwarding its stores).
    fn in_object<R>(object: &Object, ray: &Ray, f: impl FnOnce(&Ray) -> R) -> R {
        match &object.transform {
            None => f(ray),
            Some(t) => f(&ray.transformed(&t.object_from_world)),
        }
    }

    /// A shadow ray's pass through object `i`: its crossings go to `out` if it can let
    /// light through; whether it blocks the ray outright.
    fn shadow_visit(&self, i: u32, ray: &Ray, out: &mut Vec<ShadowCrossing>) -> bool {
        let object = &self.objects[i as usize];
        if !object.shadow.casts() || !object.admits(ray) {
            return false;
        }
        Self::in_object(object, ray, |local| {
            if object.shadow.filters() {
                object.shape.for_each_crossing(local, |t, part| {
                    out.push(ShadowCrossing {
                        t,
                        object: ObjectId(i),
                        part,
                    })
                });
            }
            object.shadow.blocks() && object.shape.occludes(local)
        })
    }

    /// Whether object `i` can let light through to a shadow ray.
    fn filters_shadows(&self, i: u32) -> bool {
        self.objects[i as usize].shadow.filters()
    }

    /// The material a ray meets where it crosses `object` at distance `t` on `part`: its
    /// interior texture where the surface faces away from the ray.
    fn crossing_material(&self, object: &Object, ray: &Ray, t: f64, part: u32) -> &Material {
        if object.back_material() == object.material {
            return self.material(object.material);
        }
        let point = ray.at(t);
        let normal = match &object.transform {
            None => object.shape.normals(point, part).0,
            Some(tr) => {
                let local = tr.object_from_world.transform_point3(point);
                tr.normal_to_world * object.shape.normals(local, part).0
            }
        };
        self.material(object.side(normal, ray.direction))
    }

    /// Whether world point `p` is inside `object` (POV-Ray's inside test; thin shapes have no
    /// inside; `inverse` swaps).
    pub fn contains(&self, object: &Object, p: DVec3) -> bool {
        let local = object
            .transform
            .as_ref()
            .map_or(p, |t| t.object_from_world.transform_point3(p));
        object.shape.contains(local) != object.inverse
    }

    /// Calls `f`, in increasing order, with the index of each object whose box may hold `p`
    /// (every unbounded one included).
    fn each_near(&self, p: DVec3, mut f: impl FnMut(u32)) {
        let holds = |lo: DVec3, hi: DVec3| p.cmpge(lo).all() && p.cmple(hi).all();
        match &self.index {
            Some(index) => {
                thread_local! {
                    static NEAR: std::cell::RefCell<Vec<u32>> = const { std::cell::RefCell::new(Vec::new()) };
                }
                NEAR.with_borrow_mut(|near| {
                    near.clear();
                    near.extend_from_slice(&index.unbounded);
                    index.each_kept(holds, |i| near.push(i));
                    near.sort_unstable();
                    near.iter().for_each(|&i| f(i));
                });
            }
            None => {
                for (i, bounds) in self.scan_bounds.iter().enumerate() {
                    if bounds.is_none_or(|(lo, hi)| holds(lo, hi)) {
                        f(i as u32);
                    }
                }
            }
        }
    }

    /// A ray leaving the surface at `hit` in direction `dir` (origin offset off the surface).
    pub fn spawn(&self, hit: &SurfaceHit, from: DVec3, dir: DVec3) -> Ray {
        Ray::new(
            offset_origin(
                hit.point,
                hit.geometric_normal,
                dir,
                from.abs().max_element(),
            ),
            dir,
        )
    }
}

/// A crossing of a shadow ray with the surface of an object that may let light through.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowCrossing {
    /// Distance along the ray (in units of its direction's length).
    pub t: f64,
    /// The object crossed.
    pub object: ObjectId,
    /// Which part of its shape.
    pub part: u32,
}

/// The kind of a ray, as far as objects hide from it (POV-Ray's ray flags): a camera ray
/// and the rays that go on through transparent surfaces are image rays, those reflected on
/// their way are reflected rays, and the rays a radiosity sample shoots (and all they spawn)
/// are radiosity rays; a sample's own ray is neither an image ray nor a reflected one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Seer {
    /// Reflected on its way (`no_reflection` hides from it; `no_image` does not).
    pub reflected: bool,
    /// Shot by a radiosity sample, or spawned by such a ray (`no_radiosity` hides from it).
    pub radiosity: bool,
    /// A radiosity sample's own ray (`no_image` does not hide from it).
    pub sample: bool,
}

impl Seer {
    /// The same kind of ray after a reflection.
    pub fn reflected(self) -> Seer {
        Seer {
            reflected: true,
            sample: false,
            ..self
        }
    }

    /// The same kind of ray after passing through a surface.
    pub fn transmitted(self) -> Seer {
        Seer {
            sample: false,
            ..self
        }
    }
}

/// What transport asks of the scene's geometry: the one interface through which light's
/// paths meet the objects (design: the scene answers, transport decides what light does).
/// Called with static dispatch only.
pub trait Queries {
    /// The nearest hit along a ray traced for the picture, of the objects that do not hide
    /// from `seer`'s kind of ray (`no_image`, `no_reflection`, `no_radiosity`). `hint` is an
    /// object to test first, as the one a neighbouring ray hit: the walk through the object
    /// tree then starts with the hit's distance and leaves out what lies beyond; the hit is
    /// the same whatever the hint (ties go by POV-Ray's order, not the order of the tests).
    fn nearest_hit(&self, ray: &Ray, seer: Seer, hint: Option<u32>) -> Option<Hit>;

    /// [`Queries::nearest_hit`] for each of up to eight rays (a packet: neighbouring camera
    /// rays), into `hits`: the same hits, found together.
    fn nearest_hits(&self, rays: &[Ray], seer: Seer, hint: Option<u32>, hits: &mut [Option<Hit>]);

    /// Surface details at a hit.
    fn surface(&self, ray: &Ray, hit: &Hit) -> SurfaceHit;

    /// Occlusion: an opaque object that casts shadows and meets `ray` within its extent (the
    /// first found), if any; `skip` is not tested (known not to).
    fn blocker(&self, ray: &Ray, skip: Option<u32>) -> Option<u32>;

    /// Whether object `i` is one [`Queries::blocker`] finds: opaque, casting shadows, and
    /// meeting `ray` within its extent.
    fn blocks(&self, ray: &Ray, i: u32) -> bool;

    /// [`Queries::blocker`] and the crossings along `ray` with every object that casts
    /// shadows and may let light through, in one pass over the objects: whether an opaque
    /// object blocks `ray` (the pass then stops, `out` holding part of the crossings), else
    /// every crossing appended to `out`, in no particular order.
    fn shadow_pass(&self, ray: &Ray, out: &mut Vec<ShadowCrossing>) -> bool;

    /// What the surface lets through at a crossing (its surface worked out, as for a camera
    /// ray's hit, where the material's patterns see more than the point: uv mapping, slope,
    /// aoi).
    fn crossing_filter(&self, ray: &Ray, c: &ShadowCrossing) -> Rgb;

    /// The inside test: whether world point `p` is inside object `id` (POV-Ray's; thin
    /// shapes have no inside; `inverse` swaps).
    fn inside(&self, id: ObjectId, p: DVec3) -> bool;

    /// Whether a ray starting at `p` (a camera's) starts inside object `id`: as POV-Ray finds
    /// the objects a camera ray starts in, the point must lie in the object's bounding box
    /// too (a disc's inside is a half-space, but a camera outside the disc's flat box does not
    /// start in it; its medium would change the Fresnel reflection of glass the ray leaves).
    fn starts_inside(&self, id: ObjectId, p: DVec3) -> bool;

    /// Calls `f`, in increasing order of id, with each object a ray starting at `p` starts
    /// inside ([`Queries::starts_inside`]), finding them through the objects' boxes.
    fn enclosing(&self, p: DVec3, f: impl FnMut(ObjectId));

    /// Area-light culling: the objects that could meet a shadow ray running from near
    /// `hull`'s apex to any point of its base (the unbounded objects it does not exclude, and
    /// the bounded ones whose box it does not exclude), appended to `out`. The apex lies on
    /// object `from`: a plane cannot meet a shadow ray leaving its own surface (the ray starts
    /// off it, on the side it travels to), so a plane `from` is left out.
    fn shadow_candidates(&self, hull: &ShadowHull, from: Option<ObjectId>, out: &mut Vec<u32>);

    /// Whether some object of `candidates` can let light through to a shadow ray (then only
    /// transport's shadow walk tells what reaches the light).
    fn any_filters_shadows(&self, candidates: &[u32]) -> bool;

    /// Whether an opaque object among `candidates` blocks the shadow ray: when no candidate
    /// filters shadows ([`Queries::any_filters_shadows`]) and every object the ray can meet is
    /// a candidate, the ray's transmittance is 0 if so and 1 if not.
    fn blocked_among(&self, ray: &Ray, candidates: &[u32]) -> bool;

    /// [`Queries::shadow_pass`] over `candidates` only: the same answer when every object
    /// the ray can meet is a candidate ([`Queries::shadow_candidates`]).
    fn shadow_pass_among(
        &self,
        ray: &Ray,
        candidates: &[u32],
        out: &mut Vec<ShadowCrossing>,
    ) -> bool;
}

impl Queries for Scene {
    #[inline]
    fn nearest_hit(&self, ray: &Ray, seer: Seer, hint: Option<u32>) -> Option<Hit> {
        self.nearest(ray, self.any_hidden.then_some(seer), hint)
    }

    #[inline]
    fn nearest_hits(&self, rays: &[Ray], seer: Seer, hint: Option<u32>, hits: &mut [Option<Hit>]) {
        self.nearest_packet(rays, self.any_hidden.then_some(seer), hint, hits)
    }

    #[inline]
    fn surface(&self, ray: &Ray, hit: &Hit) -> SurfaceHit {
        let object = &self.objects[hit.object.0 as usize];
        let point = ray.at(hit.t);
        let (normal, geometric) = match &object.transform {
            None => object.shape.normals(point, hit.part),
            Some(t) => {
                let local = t.object_from_world.transform_point3(point);
                let (n, g) = object.shape.normals(local, hit.part);
                (t.normal_to_world * n, t.normal_to_world * g)
            }
        };
        // (Most shapes give one normal for both: it is normalised once, to the same bits.)
        let same = geometric == normal;
        let normal = normal.normalize();
        let mut geometric_normal = if same { normal } else { geometric.normalize() };
        if !same && geometric_normal.dot(normal) < 0.0 {
            geometric_normal = -geometric_normal;
        }
        let material = object.side(normal, ray.direction);
        let uv = if self.material(material).uses_uv() {
            object.uv(point, hit.part)
        } else {
            glam::DVec2::ZERO
        };
        let corners = if self.material(material).uses_corners() {
            object.corners(point, hit.part)
        } else {
            Default::default()
        };
        SurfaceHit {
            point,
            texture_point: point,
            normal,
            geometric_normal,
            material,
            object: hit.object,
            surface: crate::pattern::Surface {
                point,
                // (POV-Ray's slope and aoi see the normal turned to face the ray.)
                normal: if normal.dot(ray.direction) > 0.0 {
                    -normal
                } else {
                    normal
                },
                direction: ray.direction,
                uv,
                corners,
            },
        }
    }

    fn blocker(&self, ray: &Ray, skip: Option<u32>) -> Option<u32> {
        let mut found = None;
        let mut blocks = |i: u32| {
            let yes = Some(i) != skip && self.blocks(ray, i);
            if yes {
                found = Some(i);
            }
            yes
        };
        match &self.index {
            Some(index) => {
                let _ = index.unbounded.iter().any(|&i| blocks(i)) || index.any(ray, blocks);
            }
            None => {
                let inv = ray.direction.recip();
                let _ = (self.scan_bounds.iter().enumerate())
                    .any(|(i, b)| may_hit(*b, ray, inv) && blocks(i as u32));
            }
        }
        found
    }

    #[inline]
    fn blocks(&self, ray: &Ray, i: u32) -> bool {
        let object = &self.objects[i as usize];
        object.shadow.blocks()
            && object.admits(ray)
            && Self::in_object(object, ray, |local| object.shape.occludes(local))
    }

    fn shadow_pass(&self, ray: &Ray, out: &mut Vec<ShadowCrossing>) -> bool {
        let mut visit = |i: u32| self.shadow_visit(i, ray, out);
        match &self.index {
            Some(index) => index.unbounded.iter().any(|&i| visit(i)) || index.any(ray, visit),
            None => {
                let inv = ray.direction.recip();
                (self.scan_bounds.iter().enumerate())
                    .any(|(i, b)| may_hit(*b, ray, inv) && visit(i as u32))
            }
        }
    }

    fn shadow_pass_among(
        &self,
        ray: &Ray,
        candidates: &[u32],
        out: &mut Vec<ShadowCrossing>,
    ) -> bool {
        let inv = ray.direction.recip();
        candidates.iter().any(|&i| {
            // (A scene with a top-level index keeps no boxes per object: the shape decides.)
            let bounds = self.scan_bounds.get(i as usize).copied().flatten();
            may_hit(bounds, ray, inv) && self.shadow_visit(i, ray, out)
        })
    }

    fn crossing_filter(&self, ray: &Ray, c: &ShadowCrossing) -> Rgb {
        let (i, t, part) = (c.object.0, c.t, c.part);
        let object = &self.objects[i as usize];
        let caustics = self.interior(object).caustics;
        let material = self.crossing_material(object, ray, t, part);
        if !material.uses_surface() && caustics == 0.0 {
            return material.filter_at(ray.at(t));
        }
        let hit = Hit {
            t,
            object: ObjectId(i),
            part,
        };
        let s = self.surface(ray, &hit);
        let material = self.material(s.material);
        if caustics != 0.0 {
            let d = ray.direction / ray.direction.length();
            // (The normal turned to face the shadow ray, as POV-Ray turns it.)
            let n = if s.normal.dot(d) > 0.0 {
                -s.normal
            } else {
                s.normal
            };
            return material.filter_with_caustics(s.point, &s.surface, (n, d), caustics);
        }
        material.filter_on(s.point, &s.surface)
    }

    fn inside(&self, id: ObjectId, p: DVec3) -> bool {
        self.contains(&self.objects[id.0 as usize], p)
    }

    fn starts_inside(&self, id: ObjectId, p: DVec3) -> bool {
        let object = &self.objects[id.0 as usize];
        // (The inside test first: an orthographic camera asks this for every ray, and the box
        // is worked out from the object's transformation.)
        self.contains(object, p)
            && object
                .world_bounds()
                .is_none_or(|(lo, hi)| p.cmpge(lo).all() && p.cmple(hi).all())
    }

    fn enclosing(&self, p: DVec3, mut f: impl FnMut(ObjectId)) {
        self.each_near(p, |i| {
            if self.starts_inside(ObjectId(i), p) {
                f(ObjectId(i));
            }
        });
    }

    fn shadow_candidates(&self, hull: &ShadowHull, from: Option<ObjectId>, out: &mut Vec<u32>) {
        let own_plane = |i: u32| {
            from.is_some_and(|f| f.0 == i)
                && matches!(self.objects[i as usize].shape, Shape::Plane(_))
        };
        match &self.index {
            Some(index) => {
                let objects = &self.objects;
                out.extend(
                    (index.unbounded.iter().copied()).filter(|&i| {
                        !own_plane(i) && !hull.excludes_unbounded(&objects[i as usize])
                    }),
                );
                index.each_kept(|lo, hi| !hull.excludes(lo, hi), |i| out.push(i));
            }
            None => {
                for (i, b) in self.scan_bounds.iter().enumerate() {
                    let kept = match b {
                        Some((lo, hi)) => !hull.excludes(*lo, *hi),
                        None => !own_plane(i as u32) && !hull.excludes_unbounded(&self.objects[i]),
                    };
                    if kept {
                        out.push(i as u32);
                    }
                }
            }
        }
    }

    fn any_filters_shadows(&self, candidates: &[u32]) -> bool {
        candidates.iter().any(|&i| self.filters_shadows(i))
    }

    fn blocked_among(&self, ray: &Ray, candidates: &[u32]) -> bool {
        let inv = ray.direction.recip();
        candidates.iter().any(|&i| {
            let object = &self.objects[i as usize];
            // (A scene with a top-level index keeps no boxes per object: the shape decides.)
            let bounds = self.scan_bounds.get(i as usize).copied().flatten();
            object.shadow.casts()
                && may_hit(bounds, ray, inv)
                && object.admits(ray)
                && Self::in_object(object, ray, |local| object.shape.occludes(local))
        })
    }
}

/// Whether an interior fades light along shadow rays (POV-Ray: positive `fade_power` and a
/// `fade_distance` that is not zero).
pub fn fades(interior: &Interior) -> bool {
    interior.fade_power > 0.0 && interior.fade_distance.abs() > 1e-10
}

/// Whether the ray may meet a box (slab test); unbounded objects always may.
fn may_hit(bounds: Option<(DVec3, DVec3)>, ray: &Ray, inv: DVec3) -> bool {
    let Some((lo, hi)) = bounds else { return true };
    let t0 = (lo - ray.origin) * inv;
    let t1 = (hi - ray.origin) * inv;
    let near = t0.min(t1).max_element().max(ray.tmin);
    let far = t0.max(t1).min_element().min(ray.tmax);
    // NaN (origin on a slab plane with a zero direction component) must not reject.
    near.partial_cmp(&far) != Some(std::cmp::Ordering::Greater)
}

/// The convex region that every shadow ray from near an apex (a shading point) to a point of
/// a parallelogram (an area light's extent) runs through: the pyramid on the parallelogram,
/// as five planes. Objects whose boxes lie wholly outside one plane cannot shadow the point
/// from any point of the light.
#[derive(Clone, Copy, Debug)]
pub struct ShadowHull {
    /// Unit normals pointing inward, and each plane's offset (n·x + d ≥ 0 inside).
    planes: [(DVec3, f64); 5],
    /// Slack for the rays' origins (moved off the surface) and rounding.
    margin: f64,
    /// How far it is grown on every side ([`ShadowHull::grown`]).
    grow: f64,
    /// The apex and the base's corners.
    vertices: [DVec3; 5],
}

impl ShadowHull {
    /// The hull from `apex` to the parallelogram `corners` (in order around it); `None` when
    /// it is degenerate (the apex in the parallelogram's plane, or a parallelogram of no
    /// area), where nothing may be culled.
    pub fn new(apex: DVec3, corners: [DVec3; 4]) -> Option<ShadowHull> {
        let scale = corners.iter().fold(apex.abs().max_element(), |m, c| {
            m.max(c.abs().max_element())
        });
        let margin = 1e-7 * (1.0 + scale);
        let plane = |n: DVec3, through: DVec3, inside: DVec3| -> Option<(DVec3, f64)> {
            let length = n.length();
            if length.is_nan() || length <= 1e-12 * (1.0 + scale * scale) {
                return None;
            }
            let n = n / length;
            let n = if n.dot(inside - through) < 0.0 { -n } else { n };
            // The inside point must be clearly inside, or the plane is not a face.
            (n.dot(inside - through) > margin).then_some((n, -n.dot(through)))
        };
        let base = plane(
            (corners[1] - corners[0]).cross(corners[3] - corners[0]),
            corners[0],
            apex,
        )?;
        let mut planes = [base; 5];
        for k in 0..4 {
            let (a, b) = (corners[k], corners[(k + 1) % 4]);
            planes[k + 1] = plane((a - apex).cross(b - apex), apex, corners[(k + 2) % 4])?;
        }
        let vertices = [apex, corners[0], corners[1], corners[2], corners[3]];
        Some(ShadowHull {
            planes,
            margin,
            grow: 0.0,
            vertices,
        })
    }

    /// The hull grown by `distance` on every side: it then holds the hulls of every apex
    /// within `distance` of its own (and every base within `distance` of its own).
    pub fn grown(self, distance: f64) -> ShadowHull {
        ShadowHull {
            grow: self.grow + distance,
            ..self
        }
    }

    /// Whether the unbounded `object` cannot meet a ray inside the hull: a plane with every
    /// vertex of the hull clearly on one side of it (tested in the object's space, where its
    /// rays are).
    fn excludes_unbounded(&self, object: &Object) -> bool {
        let Shape::Plane(plane) = &object.shape else {
            return false;
        };
        let local = self.vertices.map(|v| match &object.transform {
            None => v,
            Some(t) => t.object_from_world.transform_point3(v),
        });
        let scale = local
            .iter()
            .fold(plane.distance.abs(), |m, v| m.max(v.abs().max_element()));
        // (Growing it by g moves a plane's distance to it by at most g times the longest
        // stretch of the object's transformation, bounded by its matrix's Frobenius norm.)
        let stretch = match &object.transform {
            None => 1.0,
            Some(t) => {
                let m = &t.object_from_world;
                let axis = |a: glam::DVec4| a.truncate().length_squared();
                (axis(m.x_axis) + axis(m.y_axis) + axis(m.z_axis)).sqrt()
            }
        };
        let margin = 1e-7 * (1.0 + scale) + self.grow * stretch;
        let side = local.map(|v| plane.normal.dot(v) - plane.distance);
        side.iter().all(|&s| s > margin) || side.iter().all(|&s| s < -margin)
    }

    /// Whether the box [lo, hi] lies wholly outside the hull (by more than the margin) on one
    /// of its planes.
    pub fn excludes(&self, lo: DVec3, hi: DVec3) -> bool {
        self.planes.iter().any(|&(n, d)| {
            // The box corner farthest along the inward normal.
            let far = DVec3::select(n.cmpge(DVec3::ZERO), hi, lo);
            n.dot(far) + d < -(self.margin + self.grow)
        })
    }
}

/// Where `ray` enters the box `(lo, hi)` (0 if it starts inside).
fn entry_depth((lo, hi): (DVec3, DVec3), ray: &Ray) -> f64 {
    let inv = ray.direction.recip();
    let (a, b) = ((lo - ray.origin) * inv, (hi - ray.origin) * inv);
    let near = a.min(b);
    // (A zero direction component gives NaN for a point on the slab: it does not limit.)
    let mut t: f64 = 0.0;
    for v in near.to_array() {
        if v > t {
            t = v;
        }
    }
    t
}

#[cfg(test)]
mod hull_tests {
    use super::*;

    fn hull() -> ShadowHull {
        // Apex at the origin, a 2 × 2 light at height 4.
        let c = |x: f64, z: f64| DVec3::new(x, 4.0, z);
        ShadowHull::new(
            DVec3::ZERO,
            [c(-1.0, -1.0), c(1.0, -1.0), c(1.0, 1.0), c(-1.0, 1.0)],
        )
        .expect("solid")
    }

    #[test]
    fn boxes_outside_the_pyramid_are_excluded_and_boxes_on_it_are_not() {
        let h = hull();
        let b = |lo: [f64; 3], hi: [f64; 3]| h.excludes(DVec3::from(lo), DVec3::from(hi));
        // On the axis, touching a side, around the apex, around the light: kept.
        assert!(!b([-0.1, 1.0, -0.1], [0.1, 1.2, 0.1]));
        assert!(!b([0.45, 1.9, -0.1], [0.6, 2.1, 0.1]));
        assert!(!b([-0.1, -0.1, -0.1], [0.1, 0.1, 0.1]));
        assert!(!b([-2.0, 3.9, -2.0], [2.0, 4.1, 2.0]));
        // Beside the pyramid, below the apex, above the light: excluded.
        assert!(b([0.8, 1.0, -0.1], [1.0, 1.2, 0.1]));
        assert!(b([-0.1, -1.0, -0.1], [0.1, -0.5, 0.1]));
        assert!(b([-0.1, 4.5, -0.1], [0.1, 5.0, 0.1]));
    }

    /// A pyramid grown by g keeps every object that the pyramid of any apex within g of its
    /// own keeps: boxes of spheres, and planes turned and stretched by their transformation
    /// (random apexes, moves and objects, a fixed seed).
    #[test]
    fn a_grown_hull_keeps_what_the_hulls_of_nearby_apexes_keep() {
        let mut stream = crate::testing::Xorshift(0x2545_f491_4f6c_dd1d);
        let mut random = move || stream.unit();
        let mut text = String::from(
            "plane { y, -0.5 scale <1, 3, 1> rotate x * 20 }\n\
             plane { -z, -3 scale 0.5 }\nplane { x, 4.4 scale 0.25 }\n",
        );
        for _ in 0..40 {
            let (x, y, z, r) = (random(), random(), random(), random());
            text += &format!(
                "sphere {{ <{}, {}, {}>, {} }}\n",
                6.0 * x - 3.0,
                6.0 * y - 1.0,
                6.0 * z - 3.0,
                0.05 + 0.3 * r
            );
        }
        let scene = crate::testing::scene(text);
        let c = |x: f64, z: f64| DVec3::new(x, 4.0, z);
        let corners = [c(-1.0, -1.0), c(1.0, -1.0), c(1.0, 1.0), c(-1.0, 1.0)];
        let (mut near, mut far) = (Vec::new(), Vec::new());
        let mut differed = 0;
        for _ in 0..3000 {
            let apex = DVec3::new(
                4.0 * random() - 2.0,
                3.0 * random() - 1.0,
                4.0 * random() - 2.0,
            );
            let grow = 0.2 * random();
            let turn = DVec3::new(random() - 0.5, random() - 0.5, random() - 0.5);
            let moved = apex + turn.normalize() * grow * random().sqrt();
            let (Some(grown), Some(exact)) = (
                ShadowHull::new(apex, corners).map(|h| h.grown(grow)),
                ShadowHull::new(moved, corners),
            ) else {
                continue;
            };
            near.clear();
            far.clear();
            scene.shadow_candidates(&grown, None, &mut far);
            scene.shadow_candidates(&exact, None, &mut near);
            assert!(
                near.iter().all(|i| far.contains(i)),
                "{apex} {moved} {grow}"
            );
            differed += usize::from(near.len() != far.len());
        }
        // (The growth is not vacuous: the grown pyramids often keep more.)
        assert!(differed > 100, "{differed}");
    }

    #[test]
    fn a_flat_hull_is_none() {
        let c = |x: f64, z: f64| DVec3::new(x, 0.0, z);
        let corners = [c(-1.0, -1.0), c(1.0, -1.0), c(1.0, 1.0), c(-1.0, 1.0)];
        assert!(ShadowHull::new(DVec3::new(3.0, 0.0, 0.0), corners).is_none());
        let line = [c(-1.0, 0.0), c(1.0, 0.0), c(1.0, 0.0), c(-1.0, 0.0)];
        assert!(ShadowHull::new(DVec3::new(0.0, 2.0, 0.0), line).is_none());
    }
}

#[cfg(test)]
mod hint_tests {
    use super::*;

    /// A hint (an object tested first, as the object a neighbouring camera ray hit) changes
    /// no hit, even where surfaces coincide and POV-Ray's order picks among them: duplicate
    /// spheres, boxes sharing faces, a box face on a plane, coplanar discs, and a union's
    /// members; whichever object is hinted, hit or not. In an object tree and in a list.
    #[test]
    fn a_hint_changes_no_hit() {
        for (columns, lines, tree) in [(1, 5, false), (6, 8, true)] {
            let scene = coincident(columns, lines);
            assert_eq!(scene.index.is_some(), tree);
            hints_change_nothing(&scene);
        }
    }

    /// Camera rays found together as a packet meet what each meets alone, whatever the
    /// hint, among the same coincident surfaces: packets of 1 to 8 rays from one point in
    /// nearby directions (some of mixed signs along x), and of scattered rays.
    #[test]
    fn a_packet_finds_what_each_ray_finds() {
        // (And among meshes, walked together: coincident instances of one mesh of shared
        // edges and corners, in a tree and in a list.)
        let mesh = "#declare M = mesh {\n\
                    triangle { <-1, 0, -1>, <1, 0, -1>, <0, 1.5, 0> }\n\
                    triangle { <1, 0, -1>, <1, 0, 1>, <0, 1.5, 0> }\n\
                    triangle { <1, 0, 1>, <-1, 0, 1>, <0, 1.5, 0> }\n\
                    triangle { <-1, 0, 1>, <-1, 0, -1>, <0, 1.5, 0> }\n\
                    triangle { <-1, 0, -1>, <1, 0, -1>, <1, 0, 1> }\n\
                    pigment { rgb 1 } }\n\
                    plane { y, 0 pigment { rgb 0.5 } }\n";
        let instances = |count: i32| {
            let mut text = mesh.to_string();
            for k in 0..count {
                let (x, z) = (k % 4 * 2 - 4, k / 4 * 2);
                text += &format!("object {{ M translate <{x}, 0, {z}> }}\n");
            }
            text + "object { M translate <-4, 0, 0> }\n"
        };
        for (scene, tree) in [
            (coincident(6, 8), true),
            (crate::testing::scene(instances(12)), true),
            (crate::testing::scene(instances(2)), false),
        ] {
            assert_eq!(scene.index.is_some(), tree);
            packets_find_each_rays_hit(&scene);
        }
    }

    fn packets_find_each_rays_hit(scene: &Scene) {
        let objects = scene.object_count() as u32;
        let mut random = crate::testing::Xorshift(0x9ac);
        let mut hits = 0;
        for p in 0..4_000 {
            let mut at = |scale: f64| (random.unit() * 2.0 - 1.0) * scale;
            let from = DVec3::new(at(8.0), 3.0 + at(3.0), -6.0 + at(4.0));
            let to = DVec3::new(at(6.0), (at(1.0) > 0.0) as u32 as f64, at(1.0) * 8.0 + 3.0);
            let spread = [0.01, 0.2, 3.0][p % 3];
            let size = 1 + p % PACKET;
            let rays: Vec<Ray> = (0..size)
                .map(|_| {
                    let from = if p % 3 == 2 {
                        from + DVec3::new(at(4.0), at(1.0), at(2.0))
                    } else {
                        from
                    };
                    let mut d = to - from + DVec3::new(at(spread), at(spread), at(spread));
                    if p % 4 == 0 {
                        d.x = at(0.01);
                    }
                    Ray::new(from, d.normalize())
                })
                .collect();
            let hint = [None, Some(random.next_u64() as u32 % objects)][p % 2];
            let mut together = [None; PACKET];
            scene.nearest_packet(&rays, None, hint, &mut together[..size]);
            let key = |h: Option<Hit>| h.map(|h| (h.t.to_bits(), h.object, h.part));
            for (k, ray) in rays.iter().enumerate() {
                let alone = scene.nearest(ray, None, None);
                assert_eq!(key(together[k]), key(alone), "packet {p}, ray {k}");
                hits += usize::from(alone.is_some());
            }
        }
        assert!(hits > 4_000, "{hits} hits");
    }

    /// Two coincident planes, then `columns` columns of coincident objects (the first
    /// `lines` lines of each).
    fn coincident(columns: u32, lines: usize) -> Scene {
        let mut text = String::from(
            "plane { y, 0 pigment { rgb 1 } }\n\
             plane { y, 0 pigment { rgb 0.5 } }\n",
        );
        for k in 0..columns {
            let x = k as f64 * 2.0 - 5.0;
            let column = format!(
                "sphere {{ <{x}, 1, 0>, 1 pigment {{ rgb 1 }} }}\n\
                 sphere {{ <{x}, 1, 0>, 1 pigment {{ rgb 0.5 }} }}\n\
                 box {{ <{x}, 0, 2>, <{}, 1, 3> pigment {{ rgb 1 }} }}\n\
                 box {{ <{}, 0, 2>, <{}, 1, 3> pigment {{ rgb 1 }} }}\n\
                 box {{ <{x}, 0, 2>, <{}, 0.5, 2.5> pigment {{ rgb 0.2 }} }}\n\
                 disc {{ <{x}, 2, 5>, y, 1 pigment {{ rgb 1 }} }}\n\
                 disc {{ <{x}, 2, 5>, y, 0.7 pigment {{ rgb 1 }} }}\n\
                 union {{ sphere {{ <{x}, 1, 7>, 1 }} sphere {{ <{x}, 1, 7>, 1 }} pigment {{ rgb 1 }} }}\n",
                x + 1.0,
                x + 1.0,
                x + 2.0,
                x + 1.0,
            );
            for line in column.lines().take(lines) {
                text += line;
                text += "\n";
            }
        }
        crate::testing::scene(text)
    }

    fn hints_change_nothing(scene: &Scene) {
        let objects = scene.object_count() as u32;
        let mut random = crate::testing::Xorshift(0x417);
        let (mut hits, mut hinted_hits) = (0, 0);
        for _ in 0..20_000 {
            let mut at = |scale: f64| (random.unit() * 2.0 - 1.0) * scale;
            let from = DVec3::new(at(8.0), 3.0 + at(3.0), -6.0 + at(4.0));
            // (Toward points on the shared surfaces, or anywhere.)
            let to = DVec3::new(at(6.0), (at(1.0) > 0.0) as u32 as f64, at(1.0) * 8.0 + 3.0);
            let ray = Ray::new(from, (to - from).normalize());
            let plain = scene.nearest(&ray, None, None);
            hits += usize::from(plain.is_some());
            for hint in [
                random.next_u64() as u32 % objects,
                plain.map_or(0, |h| h.object.0),
            ] {
                let hinted = scene.nearest(&ray, None, Some(hint));
                let key = |h: Option<Hit>| h.map(|h| (h.t.to_bits(), h.object, h.part));
                assert_eq!(
                    key(hinted),
                    key(plain),
                    "{from} toward {to}, hinting {hint}"
                );
                hinted_hits += usize::from(plain.is_some_and(|h| h.object.0 == hint));
            }
        }
        assert!(
            hits > 10_000 && hinted_hits > 10_000,
            "{hits} hits, {hinted_hits}"
        );
    }
}
