//! The camera: the ray through each image position for every projection (POV-Ray's
//! formulas), a normal perturbing the rays, the mesh camera, focal blur (POV-Ray's adaptive
//! batches of lens rays, or lens points from a pixel's own sequence), and the camera ray
//! traced from the objects that contain its origin.

use super::transport::{MediumStack, Tracer};
use super::{Px, sampler};
use crate::geometry::Ray;
use crate::geometry::wide::PACKET;
use crate::scene::{Camera, Projection, Rgb, Scene};
use glam::DVec3;

/// The point every ray of `camera` starts from, for a projection with one eye point: its rays
/// all start inside the same objects, found once. `None` where rays start at many points
/// (orthographic, the cylinders with parallel rays, a mesh camera).
pub(super) fn one_eye_point(camera: &Camera) -> Option<DVec3> {
    match camera.projection {
        Projection::Orthographic | Projection::Cylinder { kind: 3 | 4, .. } | Projection::Mesh => {
            None
        }
        _ => Some(camera.location),
    }
}

/// The camera ray through image position (x, y) in pixel units, (i, j) being pixel centres
/// and y growing downward (POV-Ray §4.3), with POV-Ray's formulas for each projection; `None`
/// where the projection sees nothing (outside a fisheye's circle).
pub(super) fn camera_ray(scene: &Scene, width: u32, height: u32, x: f64, y: f64) -> Option<Ray> {
    use std::f64::consts::{FRAC_PI_2, PI};
    let c = &scene.camera();
    let (w, h) = (width as f64, height as f64);
    // POV-Ray's sample position: x + ½, y − ½.
    let (px, py) = (x + 0.5, y - 0.5);
    // −½ … ½ across the image, and −1 … 1.
    let (x0, y0) = (px / w - 0.5, ((h - 1.0) - py) / h - 0.5);
    let (x1, y1) = (2.0 * px / w - 1.0, 2.0 * ((h - 1.0) - py) / h - 1.0);
    let (len_right, len_up) = (c.right.length(), c.up.length());
    // The curved projections take unit vectors.
    let (r, u, d) = (c.right / len_right, c.up / len_up, c.direction.normalize());
    let along = |dir: glam::DVec3| Some(Ray::new(c.location, dir.normalize()));
    // The longitude and the distance from the centre of a point of the unit disc.
    let polar = |x0: f64, y0: f64| {
        let rad = (x0 * x0 + y0 * y0).sqrt();
        let phi = if rad == 0.0 {
            0.0
        } else if x0 < 0.0 {
            PI - (y0 / rad).asin()
        } else {
            (y0 / rad).asin()
        };
        (rad, phi)
    };
    // Each projection gives its ray and its screen point (x, y, 0) in its own measure, where
    // the camera's normal samples its pattern (POV-Ray's coordinates of each camera type).
    let (ray, screen) = match c.projection {
        Projection::Perspective => (along(c.direction + x0 * c.right + y0 * c.up), (x0, y0)),
        Projection::Orthographic => (
            Some(Ray::new(
                c.location + x0 * c.right + y0 * c.up,
                c.direction.normalize(),
            )),
            (x0, y0),
        ),
        Projection::Fisheye { angle } => {
            let (rad, phi) = polar(x1 * len_right, y1 * len_up);
            if rad > 1.0 {
                return None;
            }
            let theta = rad * angle.to_radians() / 2.0;
            let (sx, cx) = phi.sin_cos();
            let (sy, cy) = theta.sin_cos();
            (along(cx * sy * r + sx * sy * u + cy * d), (phi, theta))
        }
        Projection::Omnimax => {
            let aspect = len_right / len_up;
            let (mut x1, mut y1) = (x1, y1);
            if aspect > 1.0 {
                if aspect > 1.283458 {
                    x1 *= aspect / 1.283458;
                    y1 = (y1 - 1.0) / 1.283458 + 1.0;
                } else {
                    y1 = (y1 - 1.0) / aspect + 1.0;
                }
            } else {
                y1 /= aspect;
            }
            let (rad, phi) = polar(x1, y1);
            if rad > 1.0 {
                return None;
            }
            let theta = 1.411269 * rad - 0.09439 * rad.powi(3) + 0.25674 * rad.powi(5);
            let (sx, cx) = phi.sin_cos();
            let (sy, cy) = theta.sin_cos();
            // Nothing below 45° under the projection axis.
            if sx * sy < (135.0f64).to_radians().tan() * cy {
                return None;
            }
            (along(cx * sy * r + sx * sy * u + cy * d), (phi, theta))
        }
        Projection::Panoramic => {
            let lon = (1.0 - px / w) * PI;
            let lat = FRAC_PI_2 * y1;
            let ty = if (FRAC_PI_2 - lat.abs()).abs() < 1e-10 {
                lat.signum() * 1e10
            } else {
                lat.tan()
            };
            (
                along(lon.cos() * c.right + ty * c.up + lon.sin() * c.direction),
                (lon, lat),
            )
        }
        Projection::UltraWideAngle { angle } => {
            let angle = angle.to_radians();
            let aspect = len_up / len_right;
            let (ax, ay) = (x0 * angle, y0 * angle * aspect);
            let (sx, cx) = ax.sin_cos();
            let (sy, cy) = ay.sin_cos();
            (along(sx * r + sy * u + cx * cy * d), (ax, ay))
        }
        Projection::Cylinder { kind, angle } => {
            let angle = angle.to_radians();
            // 1 and 3 curve across the width (aspect from up), 2 and 4 across the height.
            let (sx, cx) = (x0 * angle).sin_cos();
            let (sy, cy) = (y0 * angle).sin_cos();
            let (across, up) = ((x0 * angle, y0 * len_up), (x0 * len_right, y0 * angle));
            match kind {
                1 => (along(sx * r + y0 * len_up * u + cx * d), across),
                2 => (along(x0 * len_right * r + sy * u + cy * d), up),
                3 => (
                    Some(Ray::new(
                        c.location + y0 * len_up * u,
                        (sx * r + cx * d).normalize(),
                    )),
                    across,
                ),
                _ => (
                    Some(Ray::new(
                        c.location + x0 * len_right * r,
                        (sy * u + cy * d).normalize(),
                    )),
                    up,
                ),
            }
        }
        Projection::Mesh => (
            scene
                .mesh_camera()
                .as_ref()
                .and_then(|m| m.ray(x, y, width, height, 0)),
            (0.0, 0.0),
        ),
        Projection::Spherical { h, v } => {
            let lat = y0 * v.to_radians();
            let lon = x0 * h.to_radians();
            let v1 = glam::DQuat::from_axis_angle(r, -lat) * c.direction;
            (along(glam::DQuat::from_axis_angle(u, lon) * v1), (lon, lat))
        }
    };
    bent(scene, ray, screen)
}

/// The camera's normal bends a camera ray's unit direction by its pattern at the screen
/// point.
pub(super) fn bent(scene: &Scene, ray: Option<Ray>, screen: (f64, f64)) -> Option<Ray> {
    match (&scene.camera_normal(), ray) {
        (Some(n), Some(ray)) => {
            let bent = n.perturb(glam::DVec3::new(screen.0, screen.1, 0.0), ray.direction);
            Some(Ray {
                direction: bent.normalize(),
                ..ray
            })
        }
        (_, ray) => ray,
    }
}

/// The colour seen through image position (x, y) by a `mesh_camera`: the mean of the rays
/// its faces give the sample (transparent black when they give none, as in POV-Ray).
pub(super) fn mesh_sample(
    tracer: &mut Tracer,
    mesh: &crate::scene::meshcam::MeshCamera,
    w: u32,
    h: u32,
    x: f64,
    y: f64,
) -> Px {
    let scene = tracer.scene;
    let (mut sum, mut n) = (Px::ZERO, 0u32);
    for k in 0..mesh.rays_per_pixel() {
        // (POV-Ray bends a mesh camera's rays by its normal at the screen point (0, 0).)
        let Some(ray) = bent(scene, mesh.ray(x, y, w, h, k), (0.0, 0.0)) else {
            continue;
        };
        tracer.counts.camera += 1;
        let colour = trace_primary(tracer, &None, Some(ray));
        sum += colour.extend(tracer.see_through);
        n += 1;
    }
    if n == 0 {
        return trace_primary(tracer, &None, None).extend(tracer.see_through);
    }
    sum / f64::from(n)
}

/// The colour seen through image position (x, y): one camera ray, or with focal blur
/// POV-Ray's adaptive batches of rays through the lens (counted as camera rays).
pub(super) fn sample(
    tracer: &mut Tracer,
    camera_media: &Option<MediumStack>,
    w: u32,
    h: u32,
    x: f64,
    y: f64,
) -> Px {
    let scene = tracer.scene;
    if let Some(mesh) = &scene.mesh_camera() {
        return mesh_sample(tracer, mesh, w, h, x, y);
    }
    let Some(blur) = &scene.blur() else {
        tracer.counts.camera += 1;
        let colour = trace_primary(tracer, camera_media, camera_ray(scene, w, h, x, y));
        return colour.extend(tracer.see_through);
    };
    if let Some(stream) = tracer.lens_stream {
        return lens_sampled(tracer, camera_media, (w, h), (x, y), blur, stream);
    }
    let seed = (313.0 * x + 11.0) as i32 + (311.0 * y + 17.0) as i32;
    let (mut n, mut level) = (0usize, 0usize);
    let (mut s1, mut s2) = ([0.0f64; 4], [0.0f64; 4]);
    let mut sum = Px::ZERO;
    let max = blur.max as usize;
    loop {
        let batch = blur.batches.get(level).copied().unwrap_or(4) as usize;
        level += 1;
        for _ in 0..batch.min(max - n) {
            let (dx, dy) = crate::scene::blur::Blur::subpixel(seed, n as i32);
            let ray = camera_ray(scene, w, h, x + dx, y + dy).map(|ray| {
                through_lens(scene, blur, ray, blur.lens(n, x + dx + 0.5, y + dy - 0.5))
            });
            tracer.counts.camera += 1;
            let (colour, t) = match ray {
                Some(_) => (trace_primary(tracer, camera_media, ray), 0.0),
                None => (Rgb::ZERO, 1.0),
            };
            sum += colour.extend(tracer.see_through);
            for (k, v) in [colour.x, colour.y, colour.z, t].into_iter().enumerate() {
                s1[k] += v;
                s2[k] += v * v;
            }
            n += 1;
        }
        let m = n as f64;
        let settled =
            (0..4).all(|k| (s2[k] / m - (s1[k] / m).powi(2)) / m < blur.thresholds[n - 1]);
        if (n as u32 >= blur.min && settled) || n >= max {
            break;
        }
    }
    sum / n as f64
}

/// The ray of focal blur for the pinhole ray `ray`, leaving the lens at offset `defl`: the
/// direction to the image plane (POV-Ray's unnormalised one for the perspective camera),
/// carried to the sharp plane.
pub(super) fn through_lens(
    scene: &Scene,
    blur: &crate::scene::blur::Blur,
    ray: Ray,
    defl: glam::DVec3,
) -> Ray {
    let c = &scene.camera();
    let to_plane = match c.projection {
        Projection::Perspective => {
            let axis = c.direction.normalize();
            ray.direction * (c.direction.length() / ray.direction.dot(axis))
        }
        _ => ray.direction,
    };
    Ray::new(
        c.location + defl,
        (to_plane * blur.focal_ratio - defl).normalize(),
    )
}

/// Method 3's focal blur (`sampled_blur`): sample `n` of the pixel whose seed is `seed` looks
/// through points of the lens drawn from the pixel's lens stream — 4 for the centre sample,
/// one for each further sample, so that a pixel's lens points together are a prefix of the
/// stream — instead of POV-Ray's batches; the pixel's own sampling decides how many it takes.
pub(super) fn lens_sampled(
    tracer: &mut Tracer,
    camera_media: &Option<MediumStack>,
    (w, h): (u32, u32),
    (x, y): (f64, f64),
    blur: &crate::scene::blur::Blur,
    (seed, n): (u32, u32),
) -> Px {
    let scene = tracer.scene;
    let (start, count) = if n == 0 {
        (0, LENS_FIRST_POINTS)
    } else {
        (LENS_FIRST_POINTS + n - 1, 1)
    };
    let lens_seed = sampler::stream_seed(seed, sampler::LENS_STREAM);
    let pinhole = camera_ray(scene, w, h, x, y);
    let mut sum = Px::ZERO;
    for i in start..start + count {
        let (u, v) = sampler::offset(lens_seed, i);
        // The lens disc of radius ½ (as POV-Ray's lens grid), scaled by the blur's radius.
        let (du, dv) = sampler::square_to_disc(u, v);
        let defl = blur.radius * (du * blur.x_perp - dv * blur.y_perp);
        tracer.counts.camera += 1;
        let ray = pinhole.map(|ray| through_lens(scene, blur, ray, defl));
        let colour = trace_primary(tracer, camera_media, ray);
        sum += colour.extend(tracer.see_through);
    }
    sum / f64::from(count)
}

/// The centre samples of pixels `xs` of row `y`, left to right, each handed to `f` as
/// [`sample`] gives it ([`sample_many`]).
pub(super) fn sample_row(
    tracer: &mut Tracer,
    camera_media: &Option<MediumStack>,
    size: (u32, u32),
    (xs, y): (std::ops::Range<u32>, u32),
    mut f: impl FnMut(&mut Tracer, u32, Px),
) {
    let mut points = [(0.0, 0.0); ROW_RAYS];
    for x0 in xs.clone().step_by(ROW_RAYS) {
        let run = x0..(x0 + ROW_RAYS as u32).min(xs.end);
        for (point, x) in points.iter_mut().zip(run.clone()) {
            *point = (x as f64, y as f64);
        }
        sample_many(
            tracer,
            camera_media,
            size,
            &points[..run.len()],
            |_, _| {},
            |tracer, k, v| f(tracer, x0 + k as u32, v),
        );
    }
}

/// The samples at image positions `points`, each handed to `f(tracer, k, value)` in order,
/// as [`sample`] gives them, `before(tracer, k)` called before each is traced (to set its
/// pixel's sample streams). With a plain camera (no mesh camera, no focal blur) the rays of
/// up to [`ROW_RAYS`] points are set up before the first of them is traced, so that their
/// divisions and square roots overlap one another instead of each waiting at the head of
/// its ray's walk (no AA on 10,000 spheres: 2 % faster), and the nearest hits of each eight
/// are found together ([`Tracer::trace_camera_rays`]).
pub(super) fn sample_many(
    tracer: &mut Tracer,
    camera_media: &Option<MediumStack>,
    (w, h): (u32, u32),
    points: &[(f64, f64)],
    mut before: impl FnMut(&mut Tracer, usize),
    mut f: impl FnMut(&mut Tracer, usize, Px),
) {
    let scene = tracer.scene;
    if scene.mesh_camera().is_some() || scene.blur().is_some() {
        for (k, &(x, y)) in points.iter().enumerate() {
            before(tracer, k);
            let v = sample(tracer, camera_media, w, h, x, y);
            f(tracer, k, v);
        }
        return;
    }
    let media = |ray: &Ray| camera_media.unwrap_or_else(|| MediumStack::at(scene, ray.origin));
    let mut rays = [None; ROW_RAYS];
    for (chunk, first) in points.chunks(ROW_RAYS).zip((0..).step_by(ROW_RAYS)) {
        for (ray, &(x, y)) in rays.iter_mut().zip(chunk) {
            *ray = camera_ray(scene, w, h, x, y);
        }
        let rays = &rays[..chunk.len()];
        let mut k = 0;
        while k < rays.len() {
            // A packet: the next rays the projection gives, up to eight.
            let mut packet = [Ray::new(DVec3::ZERO, DVec3::Z); PACKET];
            let mut n = 0;
            for ray in rays[k..].iter().take(PACKET).map_while(|ray| *ray) {
                packet[n] = ray;
                n += 1;
            }
            if n == 0 {
                before(tracer, first + k);
                tracer.counts.camera += 1;
                let colour = trace_primary(tracer, camera_media, None);
                f(tracer, first + k, colour.extend(tracer.see_through));
                k += 1;
                continue;
            }
            let at = first + k;
            let ahead = |tracer: &mut Tracer, j| before(tracer, at + j);
            tracer.trace_camera_rays(&packet[..n], media, ahead, |tracer, j, colour| {
                tracer.counts.camera += 1;
                f(tracer, at + j, colour.extend(tracer.see_through));
            });
            k += n;
        }
    }
}

/// Camera rays [`sample_many`] sets up at once.
const ROW_RAYS: usize = 32;

/// Method 3 with sampled focal blur: lens points the centre sample looks through.
pub(super) const LENS_FIRST_POINTS: u32 = 4;

/// Traces a camera ray, which starts inside the objects that contain its origin (black where
/// the projection has no ray, as in POV-Ray).
pub(super) fn trace_primary(
    tracer: &mut Tracer,
    camera_media: &Option<MediumStack>,
    ray: Option<Ray>,
) -> Rgb {
    let Some(ray) = ray else {
        tracer.see_through = 1.0;
        return Rgb::ZERO;
    };
    let media = camera_media.unwrap_or_else(|| MediumStack::at(tracer.scene, ray.origin));
    tracer.trace(&ray, 1, 1.0, &media)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row's samples set up together are the samples taken one by one, in order, for rows
    /// longer than a run of set-up rays and shorter, starting anywhere, with a plain camera
    /// and with focal blur (which takes them one by one), and in a scene whose objects have
    /// an index (their nearest hits found eight at a time, the camera looking along z so
    /// that a packet's rays differ in sign along x at the middle of a row), each sample's
    /// set-up called just before it is traced.
    #[test]
    fn a_row_of_samples_is_the_samples_one_by_one() {
        let objects = "light_source { <-3, 5, -4>, rgb 1 }\n\
                       plane { y, -1 pigment { checker rgb 1 rgb 0.2 } }\n\
                       sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } finish { reflection 0.3 } }\n\
                       sphere { <1.5, 0, 1>, 0.7 pigment { rgbf <1, 1, 1, 0.8> } interior { ior 1.4 } }\n";
        // (With twelve more spheres the objects have an index, whose tree packets walk.)
        let many = (0..12)
            .map(|k| {
                format!(
                    "sphere {{ <{}, {}, 2>, 0.3 pigment {{ rgb 0.7 }} }}\n",
                    k % 4 - 2,
                    k / 4
                )
            })
            .collect::<String>();
        for (camera, objects) in [
            (
                "camera { location <0, 1, -4> look_at 0 }",
                objects.to_string(),
            ),
            (
                "camera { location <0, 1, -4> look_at 0 aperture 0.3 blur_samples 4 focal_point 0 }",
                objects.to_string(),
            ),
            (
                "camera { location <0, 1, -4> look_at <0, 1, 0> }",
                format!("{objects}{many}"),
            ),
        ] {
            let scene = crate::testing::scene(format!("{camera}\n{objects}"));
            let (w, h) = (97, 40);
            for (xs, y) in [(0..97, 20), (5..38, 7), (60..61, 33)] {
                let mut tracer = Tracer::new(&scene);
                let mut row = Vec::new();
                sample_row(&mut tracer, &None, (w, h), (xs.clone(), y), |_, x, v| {
                    row.push((x, v))
                });
                let mut one = Tracer::new(&scene);
                let each: Vec<_> = xs
                    .clone()
                    .map(|x| (x, sample(&mut one, &None, w, h, x as f64, y as f64)))
                    .collect();
                assert_eq!(row, each, "{camera}: {xs:?} of row {y}");
                assert_eq!(tracer.counts.camera, one.counts.camera);
                // Each sample's set-up comes just before it is traced (a pixel's streams
                // are set for its own ray, not for the packet's last).
                let points: Vec<_> = xs.clone().map(|x| (x as f64, y as f64)).collect();
                let calls = std::cell::RefCell::new(Vec::new());
                let before = |_: &mut Tracer, k| calls.borrow_mut().push((k, 0));
                let after = |_: &mut Tracer, k, _| calls.borrow_mut().push((k, 1));
                sample_many(&mut tracer, &None, (w, h), &points, before, after);
                let expected: Vec<_> = (0..points.len()).flat_map(|k| [(k, 0), (k, 1)]).collect();
                assert_eq!(calls.into_inner(), expected, "{camera}: {xs:?} of row {y}");
            }
        }
    }
}
