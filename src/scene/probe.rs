//! Questions evaluation asks about an object it has made (`trace()`, `inside()`,
//! `min_extent`, `max_extent`): the object is built as a scene of its own and asked.

use super::Queries;
use super::{Ray, Scene};
use crate::ir;
use glam::DVec3;

/// POV-Ray's `BOUND_HUGE / 2`: the extent of an unbounded side.
const UNBOUNDED: f64 = 1e10;

struct Probe {
    scene: Scene,
}

/// The object made of `objects` (its parts, placed in the world), ready for questions.
pub fn object_query(objects: Vec<ir::Object>) -> Box<dyn ir::ObjectQuery> {
    let scene = ir::Scene {
        camera: ir::Camera::default(),
        lights: Vec::new(),
        objects,
        background: ir::Rgb::ZERO,
        background_alpha: 0.0,
        sky_sphere: None,
        fogs: Vec::new(),
        rainbows: Vec::new(),
        atmosphere: Vec::new(),
        settings: ir::Settings::default(),
    };
    Box::new(Probe {
        scene: Scene::build_owned(scene, None),
    })
}

impl ir::ObjectQuery for Probe {
    fn trace(&self, origin: DVec3, direction: DVec3) -> Option<(DVec3, DVec3)> {
        // POV-Ray's trace() ignores hits nearer than its MIN_ISECT_DEPTH.
        let mut ray = Ray::new(origin, direction);
        ray.tmin = 1e-4;
        let hit = self.scene.intersect(&ray)?;
        let surface = self.scene.surface(&ray, &hit);
        let object = &self.scene.objects[hit.object.0 as usize];
        let normal = if object.inverse {
            -surface.normal
        } else {
            surface.normal
        };
        Some((surface.point, normal))
    }

    fn inside(&self, p: DVec3) -> bool {
        self.scene.objects.iter().any(|o| self.scene.contains(o, p))
    }

    fn extent(&self) -> (DVec3, DVec3) {
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for o in &self.scene.objects {
            let (a, b) = o
                .world_bounds()
                .unwrap_or((DVec3::splat(-UNBOUNDED), DVec3::splat(UNBOUNDED)));
            lo = lo.min(a.max(DVec3::splat(-UNBOUNDED)));
            hi = hi.max(b.min(DVec3::splat(UNBOUNDED)));
        }
        if self.scene.objects.is_empty() {
            return (DVec3::ZERO, DVec3::ZERO);
        }
        // POV-Ray keeps a box as its corner and its lengths, each in single precision.
        let single = |v: DVec3| v.as_vec3().as_dvec3();
        let corner = single(lo);
        (corner, corner + single(hi - lo))
    }
}
