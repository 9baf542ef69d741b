//! The shape contract: what every shape gives the tracer, and the one list of shapes.
//!
//! A shape is plain geometry in object space that implements [`Surface`]: all its crossings
//! with a ray (POV-Ray's interior bookkeeping needs every one, not only the nearest), the
//! normals at a crossing, an inside test, its bounds and the name `--stats` counts it under.
//! [`Shape`] is an enum generated from the list at the end of this file, so the tracer calls
//! shapes through `match` (static dispatch, no `dyn` on the hot path) and counts every test in
//! one place.
//!
//! Adding a shape: a file in `geometry/` with its type and its `Surface` impl (with unit tests),
//! and one line in the list below. The scene builder turns the IR's shape into it
//! (`scene::build`), and the evaluator reads its syntax.

use super::{
    Blob, Cone, Crossings, Cuboid, Disc, HeightField, Isosurface, JuliaFractal, Lathe, Ovus,
    Parametric, Plane, Polygon, Polynomial, Prism, Quadric, Ray, Sor, Sphere, SphereSweep,
    Superellipsoid, Text, Torus, TriangleMesh, counters,
};
use glam::DVec3;
use std::sync::Arc;

/// The most searches [`walk`] makes along one ray.
const MAX_WALK: usize = 1024;

/// Every crossing of `ray` for a shape whose `search` finds only the first few from a ray's
/// start (as POV-Ray's isosurface and parametric searches do): POV-Ray walks a shadow ray from
/// crossing to crossing, each step taking the nearest crossing a search from the step before
/// finds, and so meets them all. `search` calls its second argument with the crossings it
/// finds on the ray it is given (in any order).
pub fn walk(
    ray: &Ray,
    mut f: impl FnMut(f64, u32),
    mut search: impl FnMut(&Ray, &mut dyn FnMut(f64, u32)),
) {
    let mut start = 0.0;
    // (Bounded, in case a search kept finding a crossing where it starts.)
    for _ in 0..MAX_WALK {
        let from = Ray {
            origin: ray.at(start),
            direction: ray.direction,
            tmin: ray.tmin - start,
            tmax: ray.tmax - start,
        };
        let mut nearest: Option<(f64, u32)> = None;
        search(&from, &mut |t, part| {
            if t > 0.0 && nearest.is_none_or(|(n, _)| t < n) {
                nearest = Some((t, part));
            }
        });
        match nearest {
            Some((t, part)) => {
                start += t;
                f(start, part);
            }
            None => return,
        }
    }
}

/// What a shape provides, in its own (object) space.
pub trait Surface {
    /// The name of its tests in `--stats`.
    const NAME: &'static str;

    /// Every crossing of the ray within its interval, nearest first, each with a part tag
    /// (which face or triangle) for [`Surface::normals`].
    fn intersect(&self, ray: &Ray) -> Crossings;

    /// (shading normal, geometric normal) at surface point `p` of part `part`, pointing out of
    /// the shape, not necessarily unit length.
    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3);

    /// Whether point `p` is inside (POV-Ray's inside test, which CSG-free scenes use for
    /// interiors and fog).
    fn contains(&self, p: DVec3) -> bool;

    /// The bounding box, `None` when unbounded.
    fn bounds(&self) -> Option<(DVec3, DVec3)>;

    /// Calls `f` with the distance and part of every crossing (in any order). Shapes with more
    /// crossings than [`Crossings`] holds (meshes) override it.
    fn for_each_crossing(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        let c = self.intersect(ray);
        for (&t, &part) in c.as_slice().iter().zip(c.parts()) {
            f(t, part);
        }
    }

    /// Whether anything of the shape lies on the ray (shadow rays; may stop at the first).
    fn occludes(&self, ray: &Ray) -> bool {
        !self.intersect(ray).is_empty()
    }

    /// The surface's (u, v) at object-space point `p` of part `part`, for `uv_mapping`;
    /// `None` for shapes without coordinates of their own (POV-Ray then takes the world
    /// point's x and y).
    fn uv(&self, _p: DVec3, _part: u32) -> Option<glam::DVec2> {
        None
    }
}

/// A shape behind a pointer is the shape.
macro_rules! forward_surface {
    ($ptr:ident) => {
        impl<T: Surface> Surface for $ptr<T> {
            const NAME: &'static str = T::NAME;
            #[inline]
            fn intersect(&self, ray: &Ray) -> Crossings {
                (**self).intersect(ray)
            }
            #[inline]
            fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
                (**self).normals(p, part)
            }
            fn contains(&self, p: DVec3) -> bool {
                (**self).contains(p)
            }
            fn bounds(&self) -> Option<(DVec3, DVec3)> {
                (**self).bounds()
            }
            fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
                (**self).for_each_crossing(ray, f)
            }
            fn occludes(&self, ray: &Ray) -> bool {
                (**self).occludes(ray)
            }
            fn uv(&self, p: DVec3, part: u32) -> Option<glam::DVec2> {
                (**self).uv(p, part)
            }
        }
    };
}
forward_surface!(Box);
forward_surface!(Arc);

/// Generates [`Shape`], its dispatch to [`Surface`] with the test counters, and the counters'
/// names from the list of shapes.
macro_rules! shapes {
    ($($(#[$doc:meta])* $variant:ident($ty:ty),)*) => {
        /// A shape in object space (the object's transformation carries it into the world).
        #[derive(Clone, Debug)]
        pub enum Shape {
            $($(#[$doc])* $variant($ty),)*
        }

        /// The kinds of intersection test `--stats` counts: one per shape, then a triangle
        /// inside a mesh.
        #[derive(Clone, Copy)]
        #[repr(usize)]
        enum Kind {
            $($variant,)*
            Triangle,
        }

        /// Index of one ray–triangle test inside a mesh in the counters.
        pub const TRIANGLE: usize = Kind::Triangle as usize;

        /// The names of the kinds of test, in the counters' order.
        pub const KINDS: [&str; TRIANGLE + 1] = [$(<$ty as Surface>::NAME,)* "Triangle"];

        impl Shape {
            /// The shape's index in the counters.
            #[inline]
            fn kind(&self) -> usize {
                match self {
                    $(Shape::$variant(_) => Kind::$variant as usize,)*
                }
            }

            /// Every crossing of the ray (counted).
            #[inline]
            pub fn intersect(&self, ray: &Ray) -> Crossings {
                // (The kind from the arm itself: a constant, not a second match.)
                let (crossings, kind) = match self {
                    $(Shape::$variant(s) => (s.intersect(ray), Kind::$variant as usize),)*
                };
                counters::record(kind, !crossings.is_empty());
                crossings
            }

            /// Whether the ray clearly misses a sphere (counted as a test that found
            /// nothing, as [`Shape::intersect`] would find it); false for other shapes.
            #[inline(always)]
            pub fn clearly_missed(&self, ray: &Ray) -> bool {
                let Shape::Sphere(s) = self else {
                    return false;
                };
                let missed = s.clearly_missed(ray);
                if missed {
                    counters::record(Kind::Sphere as usize, false);
                }
                missed
            }

            /// (shading normal, geometric normal) at `p` on part `part`.
            #[inline]
            pub fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
                match self {
                    $(Shape::$variant(s) => s.normals(p, part),)*
                }
            }

            /// Whether an object-space point is inside.
            pub fn contains(&self, p: DVec3) -> bool {
                match self {
                    $(Shape::$variant(s) => s.contains(p),)*
                }
            }

            /// Object-space bounding box, `None` when unbounded.
            pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
                match self {
                    $(Shape::$variant(s) => s.bounds(),)*
                }
            }

            /// Calls `f` with the distance and part of every crossing (counted as one test).
            pub fn for_each_crossing(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
                let mut any = false;
                let mut each = |t, part| {
                    any = true;
                    f(t, part)
                };
                match self {
                    $(Shape::$variant(s) => s.for_each_crossing(ray, &mut each),)*
                }
                counters::record(self.kind(), any);
            }

            /// The surface's (u, v) at object-space point `p` of part `part` (see
            /// [`Surface::uv`]).
            pub fn uv(&self, p: DVec3, part: u32) -> Option<glam::DVec2> {
                match self {
                    $(Shape::$variant(s) => s.uv(p, part),)*
                }
            }

            /// Whether anything of the shape lies on the ray (counted).
            pub fn occludes(&self, ray: &Ray) -> bool {
                let (blocked, kind) = match self {
                    $(Shape::$variant(s) => (s.occludes(ray), Kind::$variant as usize),)*
                };
                counters::record(kind, blocked);
                blocked
            }
        }
    };
}

shapes! {
    /// `sphere`.
    Sphere(Sphere),
    /// `plane`.
    Plane(Plane),
    /// `box`.
    Box(Cuboid),
    /// Cylinder or cone, in its canonical frame (the object transform includes the frame).
    Cone(Cone),
    /// `disc` (boxed: the largest shape, and a rare one, would make every object bigger).
    Disc(Box<Disc>),
    /// `torus`.
    Torus(Torus),
    /// Triangle mesh, shared between instances.
    Mesh(Arc<TriangleMesh>),
    /// `quadric` (boxed, as big as three vectors: rare shapes keep every object small).
    Quadric(Box<Quadric>),
    /// `cubic`, `quartic`, `poly` (boxed: its terms are a list).
    Polynomial(Box<Polynomial>),
    /// `polygon` (boxed: its points are a list).
    Polygon(Box<Polygon>),
    /// `text` (boxed: its outlines are a list).
    Text(Box<Text>),
    /// `prism` (boxed: its segments are a list).
    Prism(Box<Prism>),
    /// `lathe` (boxed: its segments are a list).
    Lathe(Box<Lathe>),
    /// `sor` (boxed: its pieces are a list).
    Sor(Box<Sor>),
    /// `blob` (boxed: its components are a list).
    Blob(Box<Blob>),
    /// `height_field` (boxed: its grid is shared and its smooth normals a list).
    HeightField(Box<HeightField>),
    /// `julia_fractal` (boxed: rare and as big as three vectors).
    JuliaFractal(Box<JuliaFractal>),
    /// `ovus` (boxed: rare, and seven numbers).
    Ovus(Box<Ovus>),
    /// `superellipsoid`.
    Superellipsoid(Superellipsoid),
    /// `sphere_sweep` (boxed: its segments are a list).
    SphereSweep(Box<SphereSweep>),
    /// `isosurface` (boxed: a function and its settings).
    Isosurface(Box<Isosurface>),
    /// `parametric` (boxed: three functions and their settings).
    Parametric(Box<Parametric>),
}

impl Shape {
    /// [`Shape::intersect`] of each of up to eight rays (a packet), into `out`: a mesh walks
    /// its tree once for them all.
    pub fn intersect_packet(&self, rays: &[Ray], out: &mut [Crossings]) {
        match self {
            Shape::Mesh(m) => {
                m.intersect_packet(rays, out);
                for crossings in &out[..rays.len()] {
                    counters::record(self.kind(), !crossings.is_empty());
                }
            }
            _ => {
                for (ray, crossings) in rays.iter().zip(out) {
                    *crossings = self.intersect(ray);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every object holds a `Shape`: rare or large shapes are boxed so that a million spheres
    /// stay small.
    #[test]
    fn a_shape_stays_small() {
        assert!(
            std::mem::size_of::<Shape>() <= 56,
            "{}",
            std::mem::size_of::<Shape>()
        );
        assert_eq!(KINDS.len(), TRIANGLE + 1);
        assert_eq!(KINDS[TRIANGLE], "Triangle");
    }
}
