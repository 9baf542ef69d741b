//! The camera: its items as written, resolved in POV-Ray's fixed order, focal blur, the mesh
//! camera.

use crate::diag::{Diagnostic, Span};
use crate::eval::lang::expr;
use crate::eval::value::Value;
use crate::eval::{Evaluator, Result, malformed};
use crate::ir::{self, Transform};
use crate::syntax::{Expr, Node, NodeKind, View};
use glam::DVec3;
use std::sync::Arc;

/// The camera items as written; resolved in POV-Ray's fixed order by [`resolve_camera`].
#[derive(Clone, Debug)]
pub struct CameraItems {
    projection: ir::Projection,
    location: DVec3,
    look_at: Option<DVec3>,
    direction: DVec3,
    up: DVec3,
    right: DVec3,
    sky: DVec3,
    angle: Option<(f64, Span)>,
    /// The second value of `angle` (`spherical`'s vertical angle).
    v_angle: Option<f64>,
    up_or_right_given: bool,
    transform: Option<Transform>,
    span: Span,
    /// Focal blur: aperture, (min, max) samples, focal point, confidence, variance.
    aperture: f64,
    blur_samples: (u32, u32),
    focal_point: Option<DVec3>,
    confidence: f64,
    variance: f64,
    normal: Option<Box<ir::Normal>>,
    /// `mesh_camera { … }`: what it gives before the camera's location and direction are
    /// known (offset and reversal are left for `resolve_camera`).
    mesh: Option<ir::MeshCamera>,
}

impl Default for CameraItems {
    fn default() -> CameraItems {
        let d = ir::Camera::default();
        CameraItems {
            projection: d.projection,
            location: d.location,
            look_at: None,
            direction: d.direction,
            up: d.up,
            right: d.right,
            sky: DVec3::Y,
            angle: None,
            v_angle: None,
            up_or_right_given: false,
            transform: None,
            aperture: 0.0,
            blur_samples: (0, 0),
            focal_point: None,
            confidence: 0.9,
            variance: 1.0 / 10000.0,
            normal: None,
            mesh: None,
            span: Span::default(),
        }
    }
}

impl Evaluator<'_> {
    pub(in crate::eval) fn camera_items(
        &mut self,
        node: &Node,
        mut c: CameraItems,
    ) -> Result<CameraItems> {
        c.span = node.word_span;
        let mut declared = false;
        self.each_item(&node.children, &mut |ev, item| {
            if declared && !Self::is_transform(item) {
                ev.warn(Diagnostic::warning(
                    format!(
                        "POV-Ray 3.7 refuses `{}` after a declared camera (only transformations may follow its name): trace applies it, but this scene does not render in POV-Ray",
                        item.word
                    ),
                    item.word_span,
                ));
            }
            match (item.kind, item.view()) {
                (NodeKind::Perspective, _) => c.projection = ir::Projection::Perspective,
                (NodeKind::Orthographic, _) => c.projection = ir::Projection::Orthographic,
                (_, View::Location(value)) => c.location = ev.vec3(value)?,
                (_, View::LookAt(value)) => c.look_at = Some(ev.vec3(value)?),
                (_, View::Direction(value)) => c.direction = ev.vec3(value)?,
                (_, View::Up(value)) => {
                    c.up = ev.vec3(value)?;
                    c.up_or_right_given = true;
                }
                (_, View::Right(value)) => {
                    c.right = ev.vec3(value)?;
                    c.up_or_right_given = true;
                }
                (_, View::Sky(value)) => c.sky = ev.vec3(value)?,
                (_, View::CameraBlur { value, max }) => ev.camera_blur(item, value, max, &mut c)?,
                (NodeKind::MeshCamera, _) => {
                    c.mesh = Some(ev.mesh_camera(item)?);
                    c.projection = ir::Projection::Mesh;
                }
                (NodeKind::Normal, _) => {
                    let base = c.normal.take();
                    c.normal = Some(Box::new(ev.normal(item, base)?));
                }
                (_, View::Angle { angle, vertical }) => {
                    let a = ev.float(angle)?;
                    // (`angle 0` on a perspective or orthographic camera changes nothing, as
                    // in POV-Ray.)
                    if c.projection.is_planar() && a == 0.0 {
                        return Ok(());
                    }
                    if c.projection.is_planar() && !(a > 0.0 && a < 180.0) {
                        return Err(Diagnostic::error(
                            "camera angle must be between 0 and 180 degrees",
                            angle.span,
                        ));
                    }
                    if a < 0.0 {
                        return Err(Diagnostic::error(
                            "camera angle must not be negative",
                            angle.span,
                        ));
                    }
                    c.angle = Some((a, item.span));
                    c.v_angle = match vertical {
                        Some(v) if matches!(c.projection, ir::Projection::Spherical { .. }) => {
                            Some(ev.float(v)?)
                        }
                        Some(v) => {
                            return Err(Diagnostic::error(
                                "only a spherical camera takes a second angle",
                                v.span,
                            ));
                        }
                        None => None,
                    };
                }
                (NodeKind::IdentRef, _) => match ev.lookup(item)? {
                    Value::Camera(camera) => {
                        c = *camera;
                        declared = true;
                    }
                    other => return Err(expr::type_error("a camera", &other, item.span)),
                },
                _ if Self::is_transform(item) => {
                    let t = ev.transform(item)?;
                    c.transform = Some(c.transform.unwrap_or(Transform::IDENTITY).then(t));
                }
                (_, View::Unknown { values }) if item.word == "cylinder" => {
                    let [e, ..] = values else {
                        return Err(Diagnostic::error("`cylinder` needs its type, 1 to 4", item.word_span));
                    };
                    let n = ev.float(e)?;
                    if !(1.0..5.0).contains(&n) {
                        return Err(Diagnostic::error(
                            "invalid cylinder camera type: valid are types 1 to 4",
                            e.span,
                        ));
                    }
                    c.projection = ir::Projection::Cylinder {
                        kind: n as u8,
                        angle: 90.0,
                    };
                }
                (NodeKind::CameraType, _)
                    if matches!(
                        item.word.as_str(),
                        "fisheye" | "ultra_wide_angle" | "omnimax" | "panoramic" | "spherical"
                    ) =>
                {
                    c.projection = match item.word.as_str() {
                        "fisheye" => ir::Projection::Fisheye { angle: 90.0 },
                        "ultra_wide_angle" => ir::Projection::UltraWideAngle { angle: 90.0 },
                        "omnimax" => ir::Projection::Omnimax,
                        "panoramic" => ir::Projection::Panoramic,
                        _ => ir::Projection::Spherical { h: 360.0, v: 180.0 },
                    };
                }
                (NodeKind::CameraType | NodeKind::Unknown, _) if item.word == "mesh_camera" => {
                    return Err(Diagnostic::error(
                        "`mesh_camera` takes a block: `mesh_camera { RAYS DISTRIBUTION mesh { … } }`",
                        item.word_span,
                    ));
                }
                (NodeKind::CameraType | NodeKind::Unknown, _) if item.word == "user_defined" => {
                    return Err(Diagnostic::error(
                        "unsupported: the user_defined camera (this camera type is not supported by trace yet)",
                        item.word_span,
                    ));
                }
                _ => return Err(ev.unknown_item(item, "camera")),
            }
            Ok(())
        })?;
        Ok(c)
    }
}

/// Resolves the camera items in POV-Ray's fixed order (§4.2): angle → look_at (with sky) →
/// orthographic rescale → transformations.
impl Evaluator<'_> {
    /// One focal blur item of a camera, with POV-Ray's checks.
    pub(in crate::eval) fn camera_blur(
        &mut self,
        item: &Node,
        first: &Expr,
        max: Option<&Expr>,
        c: &mut CameraItems,
    ) -> Result<()> {
        match item.word.as_str() {
            "aperture" => c.aperture = self.float(first)?,
            "focal_point" => c.focal_point = Some(self.vec3(first)?),
            "blur_samples" => {
                let a = self.float(first)?;
                if a <= 0.0 {
                    return Err(Diagnostic::error(
                        "blur_samples must be greater than 0",
                        first.span,
                    ));
                }
                c.blur_samples = match max {
                    Some(e) => {
                        let b = self.float(e)?;
                        if a > b {
                            return Err(Diagnostic::error(
                                "blur_samples: the least number of samples is above the most",
                                e.span,
                            ));
                        }
                        (a as u32, (b as u32).min(MAX_BLUR_SAMPLES))
                    }
                    None => (0, (a as u32).min(MAX_BLUR_SAMPLES)),
                };
            }
            word => {
                let v = self.float(first)?;
                let (ok, slot) = if word == "confidence" {
                    (v > 0.0 && v < 1.0, &mut c.confidence)
                } else {
                    ((0.0..=1.0).contains(&v), &mut c.variance)
                };
                if ok {
                    *slot = v;
                } else {
                    self.warn(Diagnostic::warning(
                        format!("`{word}` out of range: ignored (as POV-Ray ignores it)"),
                        first.span,
                    ));
                }
            }
        }
        if let Some(extra) = max.filter(|_| item.word != "blur_samples") {
            return Err(Diagnostic::error(
                format!("`{}` takes one value", item.word),
                extra.span,
            ));
        }
        Ok(())
    }
}

/// The most focal blur samples a pixel may take (POV-Ray has no limit; 4096 is far beyond the
/// 10 to 400 scenes use).
const MAX_BLUR_SAMPLES: u32 = 4096;

pub(in crate::eval) fn resolve_camera(
    c: &CameraItems,
    warnings: &mut Vec<Diagnostic>,
) -> Result<ir::Camera> {
    let mut direction = c.direction;
    let mut right = c.right;
    let mut up = c.up;
    let mut location = c.location;
    if let Some((angle, _)) = c.angle.filter(|_| c.projection.is_planar()) {
        // `angle` is the horizontal field of view across `right`.
        direction = direction.normalize_or_zero() * (right.length() / 2.0)
            / (angle.to_radians() / 2.0).tan();
    }
    if let Some(target) = c.look_at {
        let (dl, ul, rl) = (direction.length(), up.length(), right.length());
        // POV-Ray keeps `right` only when (up × direction)·right > 0: zero (e.g. `up z` with the
        // default direction) mirrors the image, as in POV-Ray.
        let handedness = if up.cross(direction).dot(right) > 0.0 {
            1.0
        } else {
            -1.0
        };
        let d = (target - location).normalize_or_zero();
        if d == DVec3::ZERO {
            return Err(Diagnostic::error(
                "camera look_at equals its location",
                c.span,
            ));
        }
        let r = c.sky.cross(d);
        if r.length_squared() < 1e-20 {
            warnings.push(Diagnostic::warning(
                "camera sky is parallel to the viewing direction; right kept",
                c.span,
            ));
            // POV-Ray keeps the direction of `right`, with the same handedness rule.
            let r = right.normalize_or_zero();
            direction = dl * d;
            right = handedness * rl * r;
            up = ul * d.cross(r);
        } else {
            let r = r.normalize();
            direction = dl * d;
            right = handedness * rl * r;
            up = ul * d.cross(r);
        }
    }
    if c.projection == ir::Projection::Orthographic && (!c.up_or_right_given || c.angle.is_some()) {
        let target = c.look_at.unwrap_or(DVec3::Z);
        let factor = (target - location).length() / direction.length();
        right *= factor;
        up *= factor;
    }
    if let Some(t) = c.transform {
        location = t.matrix.transform_point3(location);
        direction = t.matrix.transform_vector3(direction);
        right = t.matrix.transform_vector3(right);
        up = t.matrix.transform_vector3(up);
    }
    if direction.length_squared() == 0.0
        || right.length_squared() == 0.0
        || up.length_squared() == 0.0
    {
        return Err(Diagnostic::error(
            "camera direction, right and up must not be zero",
            c.span,
        ));
    }
    // The other projections keep their angle (POV-Ray's defaults: 90; spherical 360 by 180).
    let mut projection = c.projection;
    if let Some((a, _)) = c.angle {
        match &mut projection {
            ir::Projection::Fisheye { angle }
            | ir::Projection::UltraWideAngle { angle }
            | ir::Projection::Cylinder { angle, .. } => *angle = a,
            ir::Projection::Spherical { h, v } => (*h, *v) = (a, c.v_angle.unwrap_or(a * 0.5)),
            _ => {}
        }
    }
    // Focal blur: the sharp plane at the focal point's distance from the eye (before the
    // camera's transformations), or at the image plane's.
    let blur = (c.aperture != 0.0 && c.blur_samples.1 > 0).then(|| {
        let before = c.transform.map_or(direction, |t| {
            t.matrix.inverse().transform_vector3(direction)
        });
        let mut focal_distance = match c.focal_point {
            Some(p) => (p - c.location).length(),
            None => before.length(),
        };
        if focal_distance == 0.0 {
            focal_distance = 1.0;
        }
        ir::FocalBlur {
            aperture: c.aperture,
            min_samples: c.blur_samples.0,
            max_samples: c.blur_samples.1,
            focal_distance,
            confidence: c.confidence,
            variance: c.variance,
        }
    });
    // The mesh camera's meshes, unless a later projection replaced it. POV-Ray reads its
    // offset and direction from the location's and the direction's z, after the camera's
    // transformations.
    let mesh = c
        .mesh
        .as_ref()
        .filter(|_| projection == ir::Projection::Mesh)
        .map(|m| {
            Arc::new(ir::MeshCamera {
                offset: location.z,
                reversed: direction.z < -1e-10,
                ..m.clone()
            })
        });
    if mesh.is_some() && blur.is_some() {
        warnings.push(Diagnostic::warning(
            "focal blur is not applied to a mesh camera's rays by trace (POV-Ray blurs them)",
            c.span,
        ));
    }
    Ok(ir::Camera {
        projection,
        location,
        direction,
        right,
        up,
        blur,
        normal: c.normal.clone(),
        mesh,
    })
}

impl Evaluator<'_> {
    /// `mesh_camera { RAYS DISTRIBUTION [MAX_DISTANCE] mesh { … } … [smooth] }`, with
    /// POV-Ray's checks.
    pub(in crate::eval) fn mesh_camera(&mut self, node: &Node) -> Result<ir::MeshCamera> {
        let View::MeshCamera {
            rays: rays_expr,
            distribution: distribution_expr,
            max_distance,
        } = node.view()
        else {
            return Err(malformed(node, "a mesh_camera"));
        };
        let rays = self.float(rays_expr)?;
        if rays.is_nan() || rays < 1.0 {
            return Err(Diagnostic::error(
                "mesh_camera: rays per pixel may not be 0",
                rays_expr.span,
            ));
        }
        let distribution = self.float(distribution_expr)?;
        if !(0.0..4.0).contains(&distribution) {
            return Err(Diagnostic::error(
                "mesh_camera: unrecognized distribution method (0 to 3)",
                distribution_expr.span,
            ));
        }
        let (rays, distribution) = (rays.min(u32::MAX as f64) as u32, distribution as u8);
        if distribution >= 2 && rays != 1 {
            return Err(Diagnostic::error(
                "mesh_camera: rays per pixel must be 1 for distribution method 2 or 3",
                rays_expr.span,
            ));
        }
        let max_distance = match max_distance {
            Some(e) => self.float(e)?,
            None => 0.0,
        };
        let mut meshes = Vec::new();
        let mut smooth = None;
        self.each_item(&node.children, &mut |ev, item| {
            if item.kind == NodeKind::MeshCameraSmooth {
                smooth = Some(item.word_span);
                return Ok(());
            }
            if !matches!(item.word.as_str(), "mesh" | "mesh2") {
                return Err(Diagnostic::error(
                    format!("mesh_camera takes `mesh` or `mesh2`, not `{}`", item.word),
                    item.word_span,
                ));
            }
            let object = ev.object(item)?;
            match object.as_mesh() {
                Some(mesh) => meshes.push(mesh),
                None => {
                    return Err(Diagnostic::error(
                        "mesh_camera takes meshes only (this names another kind of object)",
                        item.word_span,
                    ));
                }
            }
            Ok(())
        })?;
        if let Some(span) = smooth.filter(|_| distribution != 3) {
            return Err(Diagnostic::error(
                "mesh_camera: `smooth` can only be used with distribution method 3",
                span,
            ));
        }
        if meshes.is_empty() {
            return Err(Diagnostic::error(
                "mesh_camera needs a mesh or mesh2",
                node.word_span,
            ));
        }
        if distribution == 0 && rays as usize > meshes.len() {
            return Err(Diagnostic::error(
                "mesh_camera: rays per pixel must be at most the number of meshes for distribution method 0",
                rays_expr.span,
            ));
        }
        if distribution == 3 && meshes.len() > 1 {
            self.warn(Diagnostic::warning(
                "mesh_camera: meshes after the first are ignored for distribution method 3 (as in POV-Ray)",
                node.word_span,
            ));
        }
        Ok(ir::MeshCamera {
            rays_per_pixel: rays,
            distribution,
            max_distance,
            meshes,
            smooth: smooth.is_some(),
            offset: 0.0,
            reversed: false,
        })
    }
}
