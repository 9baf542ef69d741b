//! Render-ready materials: a texture's pigment, normal and finish with its layers, or a
//! pattern of materials.

use super::*;

/// A resolved surface material.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Pigment.
    pub pigment: PlacedPigment,
    /// Normal perturbation, if any.
    pub normal: Option<Box<Normal>>,
    /// Layered textures: the layers beneath, bottom first (each with none of its own).
    pub under: Box<[Material]>,
    /// A pattern of materials: when given, the surface is these (and the rest unused).
    pub map: Option<Box<MaterialMap>>,
    /// Whether light may pass through somewhere (asked for every shadow ray's candidates).
    see_through: bool,
    /// Whether some pattern of it is uv-mapped.
    uses_uv: bool,
    /// Whether some pattern of it sees more of the surface than the point (uv, slope, aoi).
    uses_surface: bool,
    /// Whether it is picked by a mesh triangle's corners.
    uses_corners: bool,
    /// Finish.
    pub finish: Arc<Finish>,
}

impl Material {
    /// The material of a texture (with its layers), its patterns using noise generator
    /// `generator` unless they name their own.
    pub fn new(t: &ir::Texture, scene: crate::pattern::SceneDefaults) -> Material {
        let mut m = Material {
            pigment: t.pigment.placed(scene),
            normal: t.normal.as_deref().map(|n| Box::new(Normal::new(n, scene))),
            under: t.under.iter().map(|l| Material::new(l, scene)).collect(),
            map: t.map.as_deref().map(|m| {
                Box::new(MaterialMap {
                    blob: None,
                    by_corner: false,
                    pattern: m.pattern.with_scene(scene),
                    pattern_from_world: m.transform.as_ref().map(|t| t.matrix.inverse()),
                    world_from_pattern: m.transform.as_ref().map(|t| t.matrix),
                    normal_to_pattern: m
                        .transform
                        .as_ref()
                        .map(|t| DMat3::from_mat4(t.matrix).transpose()),
                    entries: m
                        .entries
                        .iter()
                        .map(|(v, e)| {
                            // The entries lie in the pattern's space: placed in the world
                            // (a uv-mapped entry sees (u, v, 0) instead).
                            let mut e = e.clone();
                            if let Some(t) = &m.transform {
                                if m.pattern.kind != crate::pattern::PatternKind::UvMapping {
                                    e.transform(**t);
                                }
                            }
                            (*v, Material::new(&e, scene))
                        })
                        .collect(),
                })
            }),
            finish: Arc::clone(&t.finish),
            see_through: false,
            uses_uv: false,
            uses_surface: false,
            uses_corners: false,
        };
        m.uses_uv = m
            .layers()
            .any(|l| l.pigment.uses_uv() || l.normal.as_ref().is_some_and(|n| n.uses_uv()))
            || m.map.as_ref().is_some_and(|map| {
                map.pattern.kind == crate::pattern::PatternKind::UvMapping
                    || map.entries.iter().any(|(_, e)| e.uses_uv)
            });
        m.uses_surface = m.uses_uv
            || m.layers().any(|l| l.pigment.uses_surface())
            || m.map.as_ref().is_some_and(|map| {
                matches!(
                    map.pattern.kind,
                    crate::pattern::PatternKind::Slope(_) | crate::pattern::PatternKind::Aoi
                ) || map.entries.iter().any(|(_, e)| e.uses_surface)
            });
        m.see_through = match &m.map {
            Some(map) => map.entries.iter().any(|(_, e)| e.may_be_transparent()),
            None => m.layers().all(|l| l.pigment.may_be_transparent()),
        };
        m
    }

    /// The surface of a blob whose components have textures: `entries` blended at each point
    /// by the fields of the `elements` acting there (each with its entry), in blob space
    /// (`blob_from_world` takes the world there).
    pub fn blob_blend(
        entries: Vec<Material>,
        mut elements: Vec<(BlobElement, u32)>,
        blob_from_world: Option<DMat4>,
    ) -> Material {
        // Elements of one entry side by side, so that each entry is lit once.
        elements.sort_by_key(|(_, entry)| *entry);
        let see_through = entries.iter().any(Material::may_be_transparent);
        let map = MaterialMap {
            blob: Some(elements.into_boxed_slice()),
            by_corner: false,
            pattern: crate::pattern::Pattern::new(crate::pattern::PatternKind::Average),
            pattern_from_world: blob_from_world,
            world_from_pattern: blob_from_world.map(|m| m.inverse()),
            normal_to_pattern: None,
            entries: entries.into_iter().map(|m| (0.0, m)).collect(),
        };
        let defaults = crate::pattern::SceneDefaults {
            generator: 2,
            waves: 10,
        };
        let mut m = Material::new(&ir::Texture::default(), defaults);
        m.map = Some(Box::new(map));
        m.see_through = see_through;
        m
    }

    /// The surface of a mesh whose triangles have textures of their own: `entries` picked
    /// by the corners of the triangle hit (blended across it by the point's weights when
    /// they differ, as POV-Ray blends a triangle's three textures).
    pub fn corner_blend(entries: Vec<Material>) -> Material {
        let see_through = entries.iter().any(Material::may_be_transparent);
        let uses_uv = entries.iter().any(|e| e.uses_uv);
        let map = MaterialMap {
            blob: None,
            by_corner: true,
            pattern: crate::pattern::Pattern::new(crate::pattern::PatternKind::Average),
            pattern_from_world: None,
            world_from_pattern: None,
            normal_to_pattern: None,
            entries: entries.into_iter().map(|m| (0.0, m)).collect(),
        };
        let defaults = crate::pattern::SceneDefaults {
            generator: 2,
            waves: 10,
        };
        let mut m = Material::new(&ir::Texture::default(), defaults);
        m.map = Some(Box::new(map));
        m.see_through = see_through;
        m.uses_uv = uses_uv;
        // (A shadow ray works out the corners where it crosses such a mesh.)
        m.uses_surface = true;
        m.uses_corners = true;
        m
    }

    /// Whether the material is picked by a mesh triangle's corners ([`Material::corner_blend`]):
    /// only then does a hit work them out.
    pub fn uses_corners(&self) -> bool {
        self.uses_corners
    }

    /// Whether some pattern of the material looks at the surface's (u, v) (`uv_mapping`):
    /// only then does a hit work them out.
    pub fn uses_uv(&self) -> bool {
        self.uses_uv
    }

    /// The layers, top first.
    pub fn layers(&self) -> impl Iterator<Item = &Material> {
        std::iter::once(self).chain(self.under.iter().rev())
    }

    /// Whether light may pass through somewhere (through every layer, or some material of
    /// a pattern of materials).
    pub fn may_be_transparent(&self) -> bool {
        self.see_through
    }

    /// Whether the material's colour depends on more of the surface than the point (uv
    /// mapping, slope, aoi): a shadow ray then works the surface out where it crosses it.
    pub fn uses_surface(&self) -> bool {
        self.uses_surface
    }

    /// [`Material::filter_at`] seen on `surface`.
    pub fn filter_on(&self, p: DVec3, surface: &crate::pattern::Surface) -> Rgb {
        if let Some(m) = &self.map {
            return m.blend(p, surface, |e, at| e.filter_on(at, surface));
        }
        self.layers()
            .map(|l| filter_colour(&l.pigment.colour_on(p, surface)))
            .fold(Rgb::ONE, |a, b| a * b)
    }

    /// [`Material::filter_on`] with POV-Ray's fake caustics (`interior { caustics }`): each
    /// layer's filter times 1 + |n·d|^`caustics`, `n` the surface normal `raw` as the layer's own
    /// normal pattern tilts it (if it has one), `d` the shadow ray's unit direction.
    pub fn filter_with_caustics(
        &self,
        p: DVec3,
        surface: &crate::pattern::Surface,
        (raw, d): (DVec3, DVec3),
        caustics: f64,
    ) -> Rgb {
        if let Some(m) = &self.map {
            return m.blend(p, surface, |e, at| {
                e.filter_with_caustics(at, surface, (raw, d), caustics)
            });
        }
        self.layers()
            .map(|l| {
                let n = l
                    .normal
                    .as_ref()
                    .map_or(raw, |n| n.perturb_on(p, raw, surface));
                filter_colour(&l.pigment.colour_on(p, surface))
                    * (1.0 + n.dot(d).abs().powf(caustics))
            })
            .fold(Rgb::ONE, |a, b| a * b)
    }

    /// What the surface lets through at `p`: the product over the layers of
    /// `rgb·filter + transmit` (POV-Ray's shadow texture), blended for a pattern of materials.
    pub fn filter_at(&self, p: DVec3) -> Rgb {
        // (One solid layer, glass's usual: its filter, which the product below starts from
        // one with, to the same bits.)
        if self.map.is_none() && self.under.is_empty() {
            if let Some(c) = self.pigment.solid_colour() {
                return filter_colour(c);
            }
        }
        if let Some(m) = &self.map {
            return m.blend(p, &Default::default(), |e, at| e.filter_at(at));
        }
        self.layers()
            .map(|l| filter_colour(&l.pigment.colour_at(p)))
            .fold(Rgb::ONE, |a, b| a * b)
    }
}

/// A pattern of materials (`texture_map`, `checker texture {…} texture {…}`).
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialMap {
    /// For a blob's textures: its elements (blob space) and the entry each one brings; the
    /// pattern is then unused.
    blob: Option<Box<[(BlobElement, u32)]>>,
    /// For a mesh's triangle textures: the entries are picked by the surface's corners; the
    /// pattern is then unused.
    by_corner: bool,
    pattern: crate::pattern::Pattern,
    pattern_from_world: Option<DMat4>,
    world_from_pattern: Option<DMat4>,
    /// A world normal into the pattern's space (not normalised), for an ordinary pattern of
    /// materials; `None` for a blob's or a mesh's textures, which POV-Ray lights each on its own.
    normal_to_pattern: Option<DMat3>,
    /// (value, material), each placed in the world.
    pub entries: Box<[(f64, Material)]>,
}

impl MaterialMap {
    /// The blend of `f` over the entries at world point `p`, as POV-Ray blends a pattern of
    /// textures: the entry the pattern's value picks, or the two around it weighted by the
    /// fraction between them, or for `average` every entry weighted by its value. `f` gets
    /// each entry and the point it is evaluated at (the pattern's warped point).
    pub fn blend<'m>(
        &'m self,
        p: DVec3,
        surface: &crate::pattern::Surface,
        mut f: impl FnMut(&'m Material, DVec3) -> Rgb,
    ) -> Rgb {
        if self.pattern.kind == crate::pattern::PatternKind::UvMapping {
            return f(&self.entries[0].1, surface.uv.extend(0.0));
        }
        if self.by_corner {
            let ([a, b, c], w) = surface.corners;
            let entry = |i: u32| &self.entries[i as usize].1;
            if a == b && b == c {
                return f(entry(a), p);
            }
            return f(entry(a), p) * w.x + f(entry(b), p) * w.y + f(entry(c), p) * w.z;
        }
        let q = self.pattern_from_world.map_or(p, |m| m.transform_point3(p));
        if let Some(elements) = &self.blob {
            return self.blob_blend(elements, q, p, f);
        }
        let warped = self.pattern.warp(q);
        let at = self.world_point(q, warped, p);
        if self.pattern.kind == crate::pattern::PatternKind::Average {
            let total: f64 = self.entries.iter().map(|(w, _)| w).sum();
            let mut sum = Rgb::ZERO;
            for (w, e) in self.entries.iter() {
                sum += f(e, at) * *w;
            }
            return sum / total;
        }
        let v = self
            .pattern
            .wave
            .apply(self.pattern.raw_on(warped, surface));
        let (prev, cur, t) = crate::pattern::pigment::search(&self.entries, v);
        let c = f(&self.entries[cur].1, at);
        if prev == cur {
            return c;
        }
        f(&self.entries[prev].1, at) * (1.0 - t) + c * t
    }

    /// POV-Ray's blob textures: each element acting at blob-space point `q` brings its entry
    /// with weight |field|, the weights normalised to sum 1; entries whose share is below
    /// POV-Ray's default `adc_bailout` (1/255) are skipped, each lit at world point `p`.
    fn blob_blend<'m>(
        &'m self,
        elements: &[(BlobElement, u32)],
        q: DVec3,
        p: DVec3,
        mut f: impl FnMut(&'m Material, DVec3) -> Rgb,
    ) -> Rgb {
        const BAILOUT: f64 = 1.0 / 255.0;
        let total: f64 = elements.iter().map(|(e, _)| e.density(q).abs()).sum();
        if total <= 0.0 {
            return Rgb::ZERO;
        }
        let mut sum = Rgb::ZERO;
        let mut run = (u32::MAX, 0.0);
        let mut flush = |(entry, weight): (u32, f64), sum: &mut Rgb| {
            if weight > 0.0 {
                *sum += f(&self.entries[entry as usize].1, p) * weight;
            }
        };
        for (e, entry) in elements {
            let w = e.density(q).abs() / total;
            if *entry != run.0 {
                flush(run, &mut sum);
                run = (*entry, 0.0);
            }
            if w >= BAILOUT {
                run.1 += w;
            }
        }
        flush(run, &mut sum);
        sum
    }

    /// Takes a world normal into the pattern's space (POV-Ray's warps of a texture map), if
    /// the pattern is moved.
    pub fn normal_to_pattern(&self) -> Option<&DMat3> {
        self.normal_to_pattern.as_ref()
    }

    /// The entries see the pattern's warped point: placed in the world as they are, that is
    /// the warped point taken back out of the pattern's space (`p` itself if nothing moved).
    fn world_point(&self, q: DVec3, warped: DVec3, p: DVec3) -> DVec3 {
        if warped == q {
            return p;
        }
        self.world_from_pattern
            .map_or(warped, |m| m.transform_point3(warped))
    }
}

/// `rgb·filter + transmit`: what a surface of colour `c` lets through, per channel.
pub fn filter_colour(c: &Colour) -> Rgb {
    c.rgb * c.filter + Rgb::splat(c.transmit)
}

impl Scene {
    /// POV-Ray's thin-film interference (`irid`): the factor on the light arriving from unit
    /// direction `to` and leaving along `d` at a surface of normal `n`, point `p`.
    pub fn irid(&self, finish: &Finish, to: DVec3, d: DVec3, n: DVec3, p: DVec3) -> Rgb {
        let irid = &finish.irid;
        let mut thickness = irid.thickness;
        if irid.turbulence != 0.0 {
            // A fixed turbulence (5 octaves), from 0..1 to 1 ± the amount.
            let t = crate::noise::Turbulence {
                amount: DVec3::ONE,
                octaves: 5,
                omega: 0.5,
                lambda: 2.0,
            };
            let noise = 2.0 * t.scalar(p, self.noise_generator) - 1.0;
            thickness *= 1.0 + noise * irid.turbulence;
        }
        let w = self.irid_wavelength;
        let cos_light = n.dot(to).abs();
        let cos_eye = n.dot(d.normalize()).abs();
        let interference = 2.0 * std::f64::consts::PI * thickness * (cos_light + cos_eye);
        Rgb::new(
            1.0 + irid.amount * (interference / w.x).cos(),
            1.0 + irid.amount * (interference / w.y).cos(),
            1.0 + irid.amount * (interference / w.z).cos(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::ObjectId;

    /// What a shadow ray's crossing lets through: rgb·filter + transmit for one solid layer
    /// (glass's usual, taken straight from its colour), the product over layers for a layered
    /// texture, and the pattern's colour where the pigment varies.
    #[test]
    fn filters_of_solid_layered_and_patterned_materials() {
        let scene = crate::testing::scene(
            "sphere { 0, 1 pigment { rgbft <0.2, 0.4, 0.6, 0.5, 0.25> } }\n\
             sphere { 0, 1 texture { pigment { rgbf <1, 0.5, 0.5, 0.8> } }\n\
                           texture { pigment { rgbt <0.5, 1, 1, 0.4> } } }\n\
             sphere { 0, 1 pigment { checker rgbf <1, 0, 0, 1> rgbf <0, 0, 1, 1> } }\n"
                .to_string(),
        );
        let filter = |i: u32, p: DVec3| {
            let object = scene.object(ObjectId(i));
            scene.material(object.material).filter_at(p)
        };
        let close = |a: Rgb, b: Rgb| (a - b).abs().max_element() < 1e-12;
        let p = DVec3::new(0.3, 0.2, 0.1);
        assert!(
            close(filter(0, p), Rgb::new(0.35, 0.45, 0.55)),
            "{}",
            filter(0, p)
        );
        let under = Rgb::new(0.5, 1.0, 1.0) * 0.0 + Rgb::splat(0.4);
        let top = Rgb::new(1.0, 0.5, 0.5) * 0.8;
        assert!(close(filter(1, p), top * under), "{}", filter(1, p));
        let (a, b) = (DVec3::new(0.5, 0.5, 0.5), DVec3::new(1.5, 0.5, 0.5));
        let (red, blue) = (Rgb::new(1.0, 0.0, 0.0), Rgb::new(0.0, 0.0, 1.0));
        let (fa, fb) = (filter(2, a), filter(2, b));
        assert!(
            (close(fa, red) && close(fb, blue)) || (close(fa, blue) && close(fb, red)),
            "{fa} {fb}"
        );
    }
}
