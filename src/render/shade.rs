//! POV-Ray's shading model and Whitted recursion (pov-semantics §6–7).

use crate::geometry::Ray;
use crate::scene::{Material, Rgb, Scene, SurfaceHit};
use glam::DVec3;

/// POV-Ray's `MAX_DISTANCE`: hits farther along a ray than this are ignored.
const MAX_DISTANCE: f64 = 1e7;

/// POV-Ray ignores a light whose cosine with the normal is below this.
const MIN_LIGHT_COSINE: f64 = 1e-10;

/// Counts of rays traced, for statistics.
#[derive(Clone, Copy, Debug, Default)]
pub struct RayCounts {
    /// Camera rays.
    pub camera: u64,
    /// Reflected rays.
    pub reflected: u64,
    /// Rays continued through transparent surfaces.
    pub transmitted: u64,
    /// Shadow rays.
    pub shadow: u64,
}

impl RayCounts {
    /// Adds another tally.
    pub fn add(&mut self, o: &RayCounts) {
        self.camera += o.camera;
        self.reflected += o.reflected;
        self.transmitted += o.transmitted;
        self.shadow += o.shadow;
    }
}

/// Traces rays through one scene; holds the per-thread ray tally.
pub struct Tracer<'a> {
    scene: &'a Scene,
    /// Rays traced so far by this tracer.
    pub counts: RayCounts,
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

impl<'a> Tracer<'a> {
    /// A tracer over `scene`.
    pub fn new(scene: &'a Scene) -> Tracer<'a> {
        Tracer {
            scene,
            counts: RayCounts::default(),
        }
    }

    /// The colour seen along `ray` (unit direction). `level` is the ray's trace level (a camera
    /// ray is 1) and `weight` its contribution to the pixel; rays past `max_trace_level` or
    /// below `adc_bailout` return black, as in POV-Ray.
    pub fn trace(&mut self, ray: &Ray, level: u32, weight: f64) -> Rgb {
        if level > self.scene.max_trace_level || weight < self.scene.adc_bailout {
            return Rgb::ZERO;
        }
        // POV-Ray ignores hits farther than MAX_DISTANCE (directions here are unit length).
        let mut ray = *ray;
        ray.tmax = ray.tmax.min(MAX_DISTANCE);
        let ray = &ray;
        let Some(hit) = self.scene.intersect(ray) else {
            return self.scene.background;
        };
        let surface = self.scene.surface(ray, &hit);
        self.shade(ray, &surface, level, weight)
    }

    fn shade(&mut self, ray: &Ray, hit: &SurfaceHit, level: u32, weight: f64) -> Rgb {
        let scene = self.scene;
        let material = scene.material(hit.material);
        let finish = &material.finish;
        let colour = material.colour;
        let d = ray.direction;
        // Shade the side facing the ray.
        let n = if hit.normal.dot(d) > 0.0 {
            -hit.normal
        } else {
            hit.normal
        };
        let pigment = colour.rgb;
        let att = if scene.legacy_transparency {
            1.0 - (colour.filter * pigment.max_element() + colour.transmit)
        } else {
            1.0 - colour.filter - colour.transmit
        };

        // Ambient and emission.
        let mut result =
            pigment * finish.ambient * scene.ambient_light * att + pigment * finish.emission * att;

        // Direct light: diffuse, phong, specular, with (coloured) shadows.
        for light in &scene.lights {
            if light.colour == Rgb::ZERO {
                continue;
            }
            let to_light = light.position - hit.point;
            let distance = to_light.length();
            let l = to_light / distance;
            let cos_nl = n.dot(l);
            if cos_nl < MIN_LIGHT_COSINE {
                continue;
            }
            let mut shadow_ray = scene.spawn(hit, ray.origin, l);
            shadow_ray.tmax = (light.position - shadow_ray.origin).length();
            self.counts.shadow += 1;
            let lc = light.colour * scene.transmittance(&shadow_ray);
            if lc == Rgb::ZERO {
                continue;
            }
            if finish.diffuse > 0.0 {
                result += pigment * lc * finish.diffuse * att * cos_nl.powf(finish.brilliance);
            }
            if finish.phong > 0.0 || finish.specular > 0.0 {
                let lc_metal = if finish.metallic != 0.0 {
                    let f = metallic_fresnel(cos_nl);
                    lc * (Rgb::ONE + finish.metallic * (1.0 - f) * (pigment - Rgb::ONE))
                } else {
                    lc
                };
                if finish.phong > 0.0 {
                    // Phong: the mirrored view ray against the light direction.
                    let r = d - 2.0 * d.dot(n) * n;
                    let c = r.dot(l);
                    if c > 0.0 {
                        result += finish.phong * c.powf(finish.phong_size) * lc_metal;
                    }
                }
                if finish.specular > 0.0 {
                    // Blinn: the half vector against the normal.
                    let h = (l - d).normalize_or_zero();
                    let c = n.dot(h);
                    if c > 0.0 {
                        result += finish.specular * c.powf(1.0 / finish.roughness) * lc_metal;
                    }
                }
            }
        }

        let cos_i = -d.dot(n);
        let reflectivity = self.reflectivity(material, cos_i);

        // Transmission through a surface of relative ior 1: the ray goes on unbent, at the same
        // trace level; but, as in POV-Ray, no secondary ray at all leaves a ray already at
        // max_trace_level (with max_trace_level 1, transparent objects show black).
        if material.is_transparent() && level < scene.max_trace_level {
            let mut filter = material.filter_colour();
            if finish.conserve_energy {
                filter *= (Rgb::ONE - reflectivity).min(Rgb::ONE);
            }
            if grey(filter).abs().min(1.0) > scene.adc_bailout {
                let through = scene.spawn(hit, ray.origin, d);
                self.counts.transmitted += 1;
                let w = weight * filter.abs().max_element();
                result += self.trace(&through, level, w) * filter;
            }
        }

        // Mirror reflection.
        if reflectivity.max_element() > 0.0 {
            let r = (d - 2.0 * d.dot(n) * n).normalize();
            let reflected = scene.spawn(hit, ray.origin, r);
            self.counts.reflected += 1;
            // POV-Ray weighs a plain reflection by its largest possible value (max of min and
            // max), whatever the angle; only Fresnel reflection uses the actual reflectivity.
            let r = &finish.reflection;
            let bound = if r.fresnel {
                reflectivity.max_element()
            } else {
                r.max.max_element().max(r.min.max_element())
            };
            let w = weight * bound;
            let mut seen = self.trace(&reflected, level + 1, w);
            if finish.reflection.exponent != 1.0 {
                seen = seen.max(DVec3::ZERO).powf(1.0 / finish.reflection.exponent);
            }
            result += reflectivity * seen;
        }
        result
    }

    /// POV-Ray's reflectivity for incidence cosine `cos_i` (§7.5), for a ray in air hitting a
    /// surface of ior 1 (trace has no interiors yet, so the Fresnel term sees η = 1).
    fn reflectivity(&self, material: &Material, cos_i: f64) -> Rgb {
        let r = &material.finish.reflection;
        if !r.is_some() {
            return Rgb::ZERO;
        }
        let mut reflec = if r.fresnel {
            let eta: f64 = 1.0;
            let g2 = eta * eta + cos_i * cos_i - 1.0;
            let f = if g2 <= 0.0 {
                1.0
            } else {
                let g = g2.sqrt();
                let c = cos_i;
                let a = (g - c) / (g + c);
                let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
                (0.5 * a * a * (1.0 + b * b)).clamp(0.0, 1.0)
            };
            f * r.max + (1.0 - f) * r.min
        } else {
            let frac = (1.0 - cos_i).max(0.0).powf(r.falloff);
            frac * r.max + (1.0 - frac) * r.min
        };
        if r.metallic != 0.0 {
            let f = metallic_fresnel(cos_i);
            reflec *= Rgb::ONE + r.metallic * (1.0 - f) * (material.colour.rgb - Rgb::ONE);
        }
        reflec
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn metallic_fresnel_matches_povray_table() {
        // x = 0 (normal incidence): 0.014567225/1.2544 − 0.011612903 ≈ 0.
        assert!(metallic_fresnel(1.0).abs() < 1e-6);
        // Grazing (x = 1): 0.014567225/0.0144 − 0.011612903 ≈ 1.0 (clamped).
        assert!((metallic_fresnel(0.0) - 1.0).abs() < 1e-6);
    }

    #[test]
    fn grey_uses_povray_weights() {
        assert!((grey(Rgb::ONE) - 1.0).abs() < 1e-12);
        assert_eq!(grey(Rgb::X), 0.297);
    }
}
