//! The render-ready scene: IR → dense arrays the tracer reads without interpretation.
//!
//! Transformations are composed and inverted here, once; materials are resolved and stored
//! once per distinct value; lights are collected. The renderer sees only this module's types.

use crate::geometry::{Crossings, Cuboid, Plane, Ray, Sphere, offset_origin};
use crate::ir;
use glam::{DMat3, DMat4, DVec3};

pub use crate::ir::{Colour, Finish, Gamma, Projection, Reflection, Rgb};

/// Index into [`Scene::materials`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MaterialId(pub u32);

/// Index into [`Scene::objects`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ObjectId(pub u32);

/// The scene as the tracer reads it.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The camera.
    pub camera: Camera,
    /// Point lights.
    pub lights: Vec<Light>,
    /// Objects.
    pub objects: Vec<Object>,
    /// Distinct materials.
    pub materials: Vec<Material>,
    /// Colour of escaped rays.
    pub background: Rgb,
    /// Rays at a deeper level return black.
    pub max_trace_level: u32,
    /// Rays of lower weight return black.
    pub adc_bailout: f64,
    /// Multiplies every finish's ambient.
    pub ambient_light: Rgb,
    /// Pre-3.7 surface attenuation.
    pub legacy_transparency: bool,
    /// Working gamma (applied when the film is written).
    pub gamma: Gamma,
}

/// The camera's four vectors.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// Projection.
    pub projection: Projection,
    /// Eye point.
    pub location: DVec3,
    /// Image-plane centre relative to the eye.
    pub direction: DVec3,
    /// Full image width vector.
    pub right: DVec3,
    /// Full image height vector.
    pub up: DVec3,
}

/// A point light.
#[derive(Clone, Copy, Debug)]
pub struct Light {
    /// World position.
    pub position: DVec3,
    /// Colour.
    pub colour: Rgb,
}

/// A resolved surface material.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Pigment colour (solid).
    pub colour: Colour,
    /// Finish.
    pub finish: Finish,
}

impl Material {
    /// Whether light passes through the surface (filter or transmit non-zero).
    pub fn is_transparent(&self) -> bool {
        self.colour.filter != 0.0 || self.colour.transmit != 0.0
    }

    /// `rgb·filter + transmit`: what the surface lets through, per channel.
    pub fn filter_colour(&self) -> Rgb {
        self.colour.rgb * self.colour.filter + Rgb::splat(self.colour.transmit)
    }
}

/// Geometry, in object space.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    /// Sphere.
    Sphere(Sphere),
    /// Infinite plane.
    Plane(Plane),
    /// Axis-aligned box.
    Box(Cuboid),
}

impl Shape {
    fn intersect(&self, ray: &Ray) -> Crossings {
        match self {
            Shape::Sphere(s) => s.intersect(ray),
            Shape::Plane(p) => p.intersect(ray),
            Shape::Box(b) => b.intersect(ray),
        }
    }

    fn normal(&self, p: DVec3) -> DVec3 {
        match self {
            Shape::Sphere(s) => s.normal(p),
            Shape::Plane(pl) => pl.normal(),
            Shape::Box(b) => b.normal(p),
        }
    }
}

/// Object-to-world transformation with what the tracer needs precomputed.
#[derive(Clone, Copy, Debug)]
pub struct ObjectTransform {
    /// Object → world.
    pub world_from_object: DMat4,
    /// World → object.
    pub object_from_world: DMat4,
    /// Inverse transpose of the linear part: takes object normals to world normals.
    pub normal_to_world: DMat3,
}

impl ObjectTransform {
    fn new(m: DMat4) -> ObjectTransform {
        let inverse = m.inverse();
        ObjectTransform {
            world_from_object: m,
            object_from_world: inverse,
            normal_to_world: DMat3::from_mat4(inverse).transpose(),
        }
    }
}

/// A placed object.
#[derive(Clone, Copy, Debug)]
pub struct Object {
    /// Geometry in object space.
    pub shape: Shape,
    /// `None` is the identity (the shape is in world space).
    pub transform: Option<ObjectTransform>,
    /// Its material.
    pub material: MaterialId,
    /// Casts no shadow.
    pub no_shadow: bool,
}

/// The nearest hit of a ray: cheap, no surface details yet.
#[derive(Clone, Copy, Debug)]
pub struct Hit {
    /// Distance along the ray (in units of the ray's direction length).
    pub t: f64,
    /// The object hit.
    pub object: ObjectId,
}

/// Surface details at a hit, computed once for the winning hit.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceHit {
    /// World-space point.
    pub point: DVec3,
    /// Outward unit normal in world space.
    pub normal: DVec3,
    /// The object's material.
    pub material: MaterialId,
}

impl Scene {
    /// Builds the render-ready scene from the IR.
    pub fn build(ir: &ir::Scene) -> Scene {
        let mut materials: Vec<Material> = Vec::new();
        let objects = ir
            .objects
            .iter()
            .map(|o| {
                let ir::Pigment::Solid(colour) = o.texture.pigment.clone();
                let material = Material {
                    colour,
                    finish: o.texture.finish.clone(),
                };
                let id = match materials.iter().position(|m| *m == material) {
                    Some(i) => i,
                    None => {
                        materials.push(material);
                        materials.len() - 1
                    }
                };
                let mut shape = match &o.shape {
                    ir::Shape::Sphere { centre, radius } => Shape::Sphere(Sphere {
                        centre: *centre,
                        radius: *radius,
                    }),
                    ir::Shape::Plane { normal, distance } => Shape::Plane(Plane {
                        normal: *normal,
                        distance: *distance,
                    }),
                    ir::Shape::Box { min, max } => Shape::Box(Cuboid {
                        min: *min,
                        max: *max,
                    }),
                };
                let mut transform = o.transform.map(|t| t.matrix);
                // Fold translations and uniform scales of spheres into the shape itself, so
                // that the common case needs no matrix per ray.
                if let (Shape::Sphere(s), Some(m)) = (&mut shape, transform) {
                    if let Some((centre, radius)) = similarity_sphere(s, &m) {
                        *s = Sphere { centre, radius };
                        transform = None;
                    }
                }
                Object {
                    shape,
                    transform: transform.map(ObjectTransform::new),
                    material: MaterialId(id as u32),
                    no_shadow: o.no_shadow,
                }
            })
            .collect();
        let c = &ir.camera;
        Scene {
            camera: Camera {
                projection: c.projection,
                location: c.location,
                direction: c.direction,
                right: c.right,
                up: c.up,
            },
            lights: ir
                .lights
                .iter()
                .map(|l| Light {
                    position: l.position,
                    colour: l.colour,
                })
                .collect(),
            objects,
            materials,
            background: ir.background,
            max_trace_level: ir.settings.max_trace_level,
            adc_bailout: ir.settings.adc_bailout,
            ambient_light: ir.settings.ambient_light,
            legacy_transparency: ir.settings.legacy_transparency,
            gamma: ir.settings.gamma,
        }
    }

    /// The material with id `id`.
    pub fn material(&self, id: MaterialId) -> &Material {
        &self.materials[id.0 as usize]
    }

    /// Crossings of a world ray with one object (object space when transformed; `t` is the
    /// same in both spaces because the direction is not renormalised).
    fn crossings(object: &Object, ray: &Ray) -> Crossings {
        match &object.transform {
            None => object.shape.intersect(ray),
            Some(t) => object
                .shape
                .intersect(&ray.transformed(&t.object_from_world)),
        }
    }

    /// The nearest hit along `ray`.
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut ray = *ray;
        for (i, object) in self.objects.iter().enumerate() {
            if let Some(t) = Self::crossings(object, &ray).first() {
                ray.tmax = t;
                best = Some(Hit {
                    t,
                    object: ObjectId(i as u32),
                });
            }
        }
        best
    }

    /// Surface details for a hit found by [`Scene::intersect`].
    pub fn surface(&self, ray: &Ray, hit: &Hit) -> SurfaceHit {
        let object = &self.objects[hit.object.0 as usize];
        let point = ray.at(hit.t);
        let normal = match &object.transform {
            None => object.shape.normal(point),
            Some(t) => {
                let local = t.object_from_world.transform_point3(point);
                (t.normal_to_world * object.shape.normal(local)).normalize()
            }
        };
        SurfaceHit {
            point,
            normal,
            material: object.material,
        }
    }

    /// What reaches the end of a shadow ray: 1 when nothing blocks it, 0 behind an opaque
    /// object, and the product of `rgb·filter + transmit` over every crossing of transparent
    /// objects (POV-Ray filters at each surface crossing). Objects with `no_shadow` are skipped.
    pub fn transmittance(&self, ray: &Ray) -> Rgb {
        let mut through = Rgb::ONE;
        for object in self.objects.iter().filter(|o| !o.no_shadow) {
            let crossings = Self::crossings(object, ray);
            if crossings.as_slice().is_empty() {
                continue;
            }
            let material = self.material(object.material);
            if !material.is_transparent() {
                return Rgb::ZERO;
            }
            for _ in crossings.as_slice() {
                through *= material.filter_colour();
            }
            if through == Rgb::ZERO {
                return through;
            }
        }
        through
    }

    /// A ray leaving the surface at `hit` in direction `dir` (origin offset off the surface).
    pub fn spawn(&self, hit: &SurfaceHit, from: DVec3, dir: DVec3) -> Ray {
        Ray::new(
            offset_origin(hit.point, hit.normal, dir, from.abs().max_element()),
            dir,
        )
    }
}

/// If `m` is a translation plus uniform scale, the sphere it maps `s` to.
fn similarity_sphere(s: &Sphere, m: &DMat4) -> Option<(DVec3, f64)> {
    let linear = DMat3::from_mat4(*m);
    let k = linear.x_axis.x;
    let is_uniform_scale = k > 0.0 && linear == DMat3::from_diagonal(DVec3::splat(k));
    is_uniform_scale.then(|| (m.transform_point3(s.centre), s.radius * k))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene_with(shape: ir::Shape, transform: DMat4) -> Scene {
        let ir = ir::Scene {
            camera: ir::Camera::default(),
            lights: vec![],
            objects: vec![ir::Object {
                shape,
                transform: Some(ir::Transform { matrix: transform }),
                texture: ir::Texture::default(),
                no_shadow: false,
                inverse: false,
            }],
            background: Rgb::ZERO,
            settings: ir::Settings::default(),
        };
        Scene::build(&ir)
    }

    #[test]
    fn transformed_sphere_equals_analytic_sphere() {
        let m = DMat4::from_translation(DVec3::new(1.0, 2.0, 3.0))
            * DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0));
        let s = scene_with(
            ir::Shape::Sphere {
                centre: DVec3::ZERO,
                radius: 1.0,
            },
            m,
        );
        // Along x through the centre the ellipsoid extends ±2.
        let r = Ray::new(DVec3::new(-10.0, 2.0, 3.0), DVec3::X);
        let hit = s.intersect(&r).expect("hit");
        assert!((hit.t - 9.0).abs() < 1e-12);
        let surf = s.surface(&r, &hit);
        assert!((surf.normal - -DVec3::X).length() < 1e-12);
        // Off-axis normal follows the inverse transpose: at (x, y) on the ellipse x²/4 + y² = 1
        // the normal is ∝ (x/4, y).
        let r = Ray::new(DVec3::new(1.0 + 2.0f64.sqrt(), 10.0, 3.0), -DVec3::Y);
        let hit = s.intersect(&r).expect("hit");
        let surf = s.surface(&r, &hit);
        let expected = DVec3::new(2.0f64.sqrt() / 4.0, 1.0 / 2.0f64.sqrt(), 0.0).normalize();
        assert!(
            (surf.normal - expected).length() < 1e-9,
            "{:?}",
            surf.normal
        );
    }

    #[test]
    fn rotated_box_is_hit_at_rotated_face() {
        let m = DMat4::from_rotation_y(std::f64::consts::FRAC_PI_4);
        let s = scene_with(
            ir::Shape::Box {
                min: DVec3::splat(-1.0),
                max: DVec3::splat(1.0),
            },
            m,
        );
        let r = Ray::new(DVec3::new(0.0, 0.0, -10.0), DVec3::Z);
        let hit = s.intersect(&r).expect("hit");
        assert!((hit.t - (10.0 - 2.0f64.sqrt())).abs() < 1e-12);
    }

    #[test]
    fn scaled_plane_keeps_t_in_world_units() {
        let m = DMat4::from_scale(DVec3::splat(3.0));
        let s = scene_with(
            ir::Shape::Plane {
                normal: DVec3::Y,
                distance: 1.0,
            },
            m,
        );
        let r = Ray::new(DVec3::new(0.0, 10.0, 0.0), -DVec3::Y);
        let hit = s.intersect(&r).expect("hit");
        assert!((hit.t - 7.0).abs() < 1e-12);
    }

    #[test]
    fn uniformly_scaled_sphere_is_folded_into_its_shape() {
        let m = DMat4::from_translation(DVec3::X) * DMat4::from_scale(DVec3::splat(2.0));
        let s = scene_with(
            ir::Shape::Sphere {
                centre: DVec3::ZERO,
                radius: 1.0,
            },
            m,
        );
        assert!(s.objects[0].transform.is_none());
        let Shape::Sphere(sphere) = s.objects[0].shape else {
            panic!("sphere expected")
        };
        assert_eq!((sphere.centre, sphere.radius), (DVec3::X, 2.0));
    }
}
