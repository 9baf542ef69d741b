//! Objects: shapes, meshes, `union` groups, `object { Name }` instances and their modifiers.
//!
//! A union is flattened into its members (trace gives `union` its grouping meaning only);
//! modifiers on the group apply to every member, and the group's texture to the members that
//! have none. Meshes are built once and shared (`Arc`) by every instance of a declaration.

use crate::diag::{Diagnostic, Span};
use crate::eval::{Evaluator, Result, Value, lang::expr::type_error, value::Vector};
use crate::ir::{self, FLAT, Interior, Mesh, Shape, Texture, Transform};
use crate::syntax::view::List;
use crate::syntax::{Expr, ExprKind, Node, NodeKind, View};
use glam::{DMat3, DVec2, DVec3};
use std::sync::Arc;

/// One shape of an object under construction.
#[derive(Clone, Debug)]
struct Part {
    shape: Shape,
    transform: Option<Transform>,
    /// The member's own texture (for a union member), if any.
    texture: Option<Texture>,
    /// The member's own interior texture (seen from inside), if any.
    interior_texture: Option<Texture>,
    /// The member's own interior, if any.
    interior: Option<Interior>,
    /// With `interior`: which of the object's own interiors it is (members of a nested union
    /// share theirs), numbered from 0 within the object; see [`ObjectValue::own_interiors`].
    interior_group: u32,
    /// For a stand-alone `smooth_triangle`: its vertex normals in the current frame. POV-Ray
    /// moves them with the triangle itself, normalising them again after every `scale` (not
    /// after `matrix` or `transform`), and interpolates those; see [`ObjectValue::transform`].
    vertex_normals: Option<[DVec3; 3]>,
    inverse: bool,
    no_shadow: bool,
    /// `no_image`, `no_reflection`, `double_illuminate`.
    sight: ir::Sight,
    /// For a part of a `light_group`: which lights light it.
    light_group: Option<ir::LightGroup>,
    /// `radiosity { importance F }`, if given.
    importance: Option<f64>,
    /// `hollow [on|off]` if given; a group's passes to members that have none (as POV-Ray).
    hollow: Option<bool>,
    /// The `bounded_by` shapes of the member it came from (a union's own are the object's).
    bounds: Vec<ir::Bound>,
}

/// An object while it is being built: one shape, or the flattened members of a union.
#[derive(Clone, Debug)]
pub struct ObjectValue {
    parts: Vec<Part>,
    /// The object's (or group's) texture, applied to parts without their own.
    texture: Option<Texture>,
    /// The object's (or group's) interior texture, applied to parts without their own.
    interior_texture: Option<Texture>,
    /// The object's (or group's) interior, applied to parts without their own.
    interior: Option<Interior>,
    /// How many distinct interiors the parts have of their own (`interior_group` counts
    /// below it); the object's interior comes after them.
    own_interiors: u32,
    /// Light sources inside a `union` (or an `object {}`): they move with it.
    pub(in crate::eval) lights: Vec<ir::Light>,
    /// A union (its `hollow` goes only to members without their own).
    is_union: bool,
    /// `global_lights` given on a `light_group`.
    global_lights: bool,
    /// `uv_mapping` before the object's texture: textures given after it see (u, v, 0).
    uv_mapping: bool,
    /// `bounded_by`: the object's bounding shapes, in the world.
    bounds: Vec<ir::Bound>,
    /// Which object this is, for the queries of trace() and its kin (0: none yet).
    pub(in crate::eval) id: u64,
}

/// The mark of a light standing directly in the `light_group` being read (its number is
/// given when the group is complete).
const OWN_GROUP: u32 = u32::MAX;

/// Whether a node is an object statement.
pub(crate) fn is_object(kind: NodeKind) -> bool {
    use NodeKind::*;
    matches!(
        kind,
        Sphere
            | Plane
            | Box
            | Cylinder
            | Cone
            | Disc
            | Torus
            | Shape
            | Triangle
            | SmoothTriangle
            | Mesh
            | Mesh2
            | MeshFile
            | Union
            | Blob
            | Isosurface
            | Parametric
            | ObjectRef
    )
}

/// A sphere or cylinder outside a blob takes no strength (a value after its `n` values).
fn no_strength(node: &Node, n: usize, strength: Option<&Expr>) -> Result<()> {
    match strength {
        Some(e) => Err(Diagnostic::error(
            format!(
                "a strength belongs to a blob's components: this {} takes {n} values",
                node.word
            ),
            e.span,
        )),
        None => Ok(()),
    }
}

/// A cone or cylinder from its ends (base, base radius, cap, cap radius); `open` among its
/// modifiers leaves the caps off.
fn cone(node: &Node, modifiers: &[Node], ends: (DVec3, f64, DVec3, f64)) -> Result<ObjectValue> {
    let (base, base_radius, cap, cap_radius) = ends;
    if base == cap {
        return Err(Diagnostic::error(
            "the two ends are the same point",
            node.word_span,
        ));
    }
    if base_radius == 0.0 && cap_radius == 0.0 {
        return Err(Diagnostic::error("both radii are zero", node.word_span));
    }
    let open = modifiers
        .iter()
        .any(|m| m.kind == NodeKind::Flag && m.word == "open");
    Ok(ObjectValue::single(Shape::Cone {
        base,
        base_radius,
        cap,
        cap_radius,
        open,
    }))
}

fn compose(t: Option<Transform>, next: Transform) -> Option<Transform> {
    Some(t.unwrap_or(Transform::IDENTITY).then(next))
}

impl ObjectValue {
    fn single(shape: Shape) -> ObjectValue {
        ObjectValue {
            parts: vec![Part {
                shape,
                transform: None,
                texture: None,
                interior_texture: None,
                interior: None,
                interior_group: 0,
                vertex_normals: None,
                inverse: false,
                no_shadow: false,
                sight: ir::Sight::default(),
                light_group: None,
                importance: None,
                hollow: None,
                bounds: Vec::new(),
            }],
            texture: None,
            interior_texture: None,
            interior: None,
            own_interiors: 0,
            lights: Vec::new(),
            is_union: false,
            global_lights: false,
            uv_mapping: false,
            bounds: Vec::new(),
            id: 0,
        }
    }

    pub(in crate::eval) fn empty() -> ObjectValue {
        ObjectValue {
            parts: Vec::new(),
            texture: None,
            interior_texture: None,
            interior: None,
            own_interiors: 0,
            lights: Vec::new(),
            is_union: false,
            global_lights: false,
            uv_mapping: false,
            bounds: Vec::new(),
            id: 0,
        }
    }

    /// The object's mesh and transformation, if it is one mesh.
    pub(in crate::eval) fn as_mesh(&self) -> Option<(Arc<Mesh>, Option<Transform>)> {
        match self.parts.as_slice() {
            [
                Part {
                    shape: Shape::Mesh(mesh),
                    transform,
                    ..
                },
            ] => Some((Arc::clone(mesh), *transform)),
            _ => None,
        }
    }

    /// Whether the object has no shapes (a light alone).
    pub(in crate::eval) fn parts_is_empty(&self) -> bool {
        self.parts.is_empty()
    }

    /// Marks every part as casting no shadow (a light's `looks_like` object).
    pub(in crate::eval) fn cast_no_shadow(&mut self) {
        self.parts.iter_mut().for_each(|p| p.no_shadow = true);
    }

    /// Keeps every part out of the light groups around it (a light's `looks_like` object: in
    /// a `light_group`, POV-Ray lights it by the lights outside every group, not the group's).
    pub(in crate::eval) fn outside_light_groups(&mut self) {
        for p in self.parts.iter_mut().filter(|p| p.light_group.is_none()) {
            p.light_group = Some(ir::LightGroup {
                groups: Vec::new(),
                global_lights: true,
            });
        }
    }

    /// Applies a transformation to the geometry and to every texture already attached.
    /// Applies a transformation; `scale` tells that it is a `scale` modifier (which makes
    /// POV-Ray normalise a smooth triangle's vertex normals).
    pub(in crate::eval) fn transform(&mut self, t: Transform, scale: bool) {
        let normal_matrix = DMat3::from_mat4(t.matrix).inverse().transpose();
        for part in &mut self.parts {
            part.transform = compose(part.transform, t);
            if let Some(normals) = &mut part.vertex_normals {
                for n in normals {
                    *n = normal_matrix * *n;
                    if scale {
                        *n = n.normalize_or_zero();
                    }
                }
            }
            for tex in [&mut part.texture, &mut part.interior_texture]
                .into_iter()
                .flatten()
            {
                tex.transform(t);
            }
            if let Some(interior) = &mut part.interior {
                interior.transform(t);
            }
            for b in &mut part.bounds {
                b.transform = compose(b.transform.take().map(|t| *t), t).map(Box::new);
            }
        }
        for b in &mut self.bounds {
            b.transform = compose(b.transform.take().map(|t| *t), t).map(Box::new);
        }
        for tex in [&mut self.texture, &mut self.interior_texture]
            .into_iter()
            .flatten()
        {
            tex.transform(t);
        }
        if let Some(interior) = &mut self.interior {
            interior.transform(t);
        }
        for light in &mut self.lights {
            crate::eval::build::light::transform_light(light, &t.matrix);
        }
    }
}

impl Evaluator<'_> {
    /// The `importance` an object's (or `#default`'s) `radiosity { … }` block gives, the last
    /// if several (each above 0 and at most 1); `context` names the block in errors.
    pub(in crate::eval) fn radiosity_importance(
        &mut self,
        block: &Node,
        context: &str,
    ) -> Result<Option<f64>> {
        let mut importance = None;
        self.each_item(&block.children, &mut |ev, item| {
            let View::Importance(e) = item.view() else {
                return Err(ev.unknown_item(item, context));
            };
            let v = ev.float(e)?;
            if !(v > 0.0 && v <= 1.0) {
                return Err(Diagnostic::error(
                    "radiosity importance must be above 0 and at most 1",
                    e.span,
                ));
            }
            importance = Some(v);
            Ok(())
        })?;
        Ok(importance)
    }

    /// Evaluates an object statement with its modifiers.
    pub(in crate::eval) fn object(&mut self, node: &Node) -> Result<ObjectValue> {
        let mut modifiers = node.children.as_slice();
        let mut object = match (node.kind, node.view()) {
            (
                _,
                View::Sphere {
                    centre,
                    radius,
                    strength,
                },
            ) => {
                no_strength(node, 2, strength)?;
                let centre = self.vec3(centre)?;
                let radius = self.float(radius)?;
                ObjectValue::single(Shape::Sphere { centre, radius })
            }
            (NodeKind::Blob, _) => {
                modifiers = &[];
                self.blob(node)?
            }
            (NodeKind::Isosurface, _) => {
                modifiers = &[];
                self.isosurface(node)?
            }
            (_, View::Parametric { uv_min, uv_max }) => {
                modifiers = &[];
                self.parametric(node, uv_min, uv_max)?
            }
            (_, View::Plane { normal, distance }) => {
                let normal = self.nonzero(normal, "plane normal")?;
                let distance = self.float(distance)?;
                // POV-Ray normalises the normal first: `plane { <0,2,0>, 1 }` is y = 1.
                ObjectValue::single(Shape::Plane {
                    normal: normal.normalize(),
                    distance,
                })
            }
            (_, View::Box { corner1, corner2 }) => {
                let a = self.vec3(corner1)?;
                let b = self.vec3(corner2)?;
                ObjectValue::single(Shape::Box {
                    min: a.min(b),
                    max: a.max(b),
                })
            }
            (
                _,
                View::Cylinder {
                    base,
                    cap,
                    radius,
                    strength,
                },
            ) => {
                no_strength(node, 3, strength)?;
                let (base, cap, radius) = (self.vec3(base)?, self.vec3(cap)?, self.float(radius)?);
                cone(node, modifiers, (base, radius, cap, radius))?
            }
            (
                _,
                View::Cone {
                    base,
                    base_radius,
                    cap,
                    cap_radius,
                },
            ) => {
                let ends = (
                    self.vec3(base)?,
                    self.float(base_radius)?,
                    self.vec3(cap)?,
                    self.float(cap_radius)?,
                );
                cone(node, modifiers, ends)?
            }
            (
                _,
                View::Disc {
                    centre,
                    normal,
                    radius,
                    holes,
                },
            ) => {
                let centre = self.vec3(centre)?;
                let normal = self.nonzero(normal, "disc normal")?.normalize();
                let radius = self.float(radius)?;
                // (Each value after the radius is the hole's radius again, as POV-Ray reads
                // them: the last counts.)
                let mut hole_radius = 0.0;
                for e in holes {
                    hole_radius = self.float(e)?;
                }
                ObjectValue::single(Shape::Disc {
                    centre,
                    normal,
                    radius,
                    hole_radius,
                })
            }
            (NodeKind::Shape, _) => {
                let shape = self.shape_table(node)?;
                let first = match &shape {
                    // POV-Ray turns every text by 0.001° about each axis before the scene's
                    // own transformations ("to fix cracks"); the faces' slight tilt shows.
                    Shape::Text(_) => Some(crate::eval::lang::expr::rotation(DVec3::splat(0.001))),
                    // A height field's grid (points, 16-bit heights) scaled to the unit box.
                    Shape::HeightField(h) => Some(glam::DMat4::from_scale(DVec3::new(
                        1.0 / f64::from(h.width - 1),
                        1.0 / 65536.0,
                        1.0 / f64::from(h.depth - 1),
                    ))),
                    _ => None,
                };
                let mut object = ObjectValue::single(shape);
                if let Some(matrix) = first {
                    object.transform(Transform { matrix }, false);
                }
                object
            }
            (_, View::Torus { major, minor }) => {
                let minor_span = minor.span;
                let major = self.float(major)?;
                let minor = self.float(minor)?;
                if minor <= 0.0 || major < 0.0 {
                    return Err(Diagnostic::error(
                        "torus radii must be positive",
                        minor_span,
                    ));
                }
                ObjectValue::single(Shape::Torus { major, minor })
            }
            (NodeKind::Triangle | NodeKind::SmoothTriangle, _) => {
                let mut mesh = Mesh {
                    world_uv: true,
                    ..Mesh::default()
                };
                self.add_triangle(&mut mesh, node, false)?;
                if mesh.triangles.is_empty() {
                    ObjectValue::empty()
                } else {
                    let normals = (mesh.normals.len() == 3)
                        .then(|| [0, 1, 2].map(|i| mesh.normals[i].as_dvec3()));
                    let mut object = ObjectValue::single(Shape::Mesh(Arc::new(mesh)));
                    object.parts[0].vertex_normals = normals;
                    object
                }
            }
            (NodeKind::Mesh, _) => {
                let mut mesh = Mesh::default();
                let split = node
                    .children
                    .iter()
                    .position(|c| !matches!(c.kind, NodeKind::Triangle | NodeKind::SmoothTriangle));
                let (triangles, rest) =
                    node.children.split_at(split.unwrap_or(node.children.len()));
                self.each_item(triangles, &mut |ev, t| {
                    if !matches!(t.kind, NodeKind::Triangle | NodeKind::SmoothTriangle) {
                        return Err(Diagnostic::error(
                            "expected a triangle or smooth_triangle here",
                            t.word_span,
                        ));
                    }
                    // A triangle of a mesh may have a texture of its own (POV-Ray allows
                    // nothing else there).
                    let mut texture = None;
                    for m in t.children.iter().filter(|c| c.kind != NodeKind::TriangleUv) {
                        if m.kind != NodeKind::Texture || texture.is_some() {
                            return Err(Diagnostic::error(
                                "a triangle inside a mesh takes only uv_vectors and one texture",
                                m.span,
                            ));
                        }
                        texture = Some(ev.texture(m)?);
                    }
                    let before = mesh.triangles.len();
                    ev.add_triangle(&mut mesh, t, true)?;
                    if mesh.triangles.len() > before {
                        let entry = match texture {
                            Some(t) => mesh_texture(&mut mesh.textures, t),
                            None => ir::OWN_TEXTURE,
                        };
                        mesh.face_textures.push([entry; 3]);
                    }
                    Ok(())
                })?;
                if mesh.textures.is_empty() {
                    mesh.face_textures.clear();
                }
                modifiers = self.inside_vector(&mut mesh, rest)?;
                if mesh.triangles.is_empty() {
                    self.warn(Diagnostic::warning(
                        "mesh without (valid) triangles: nothing to render",
                        node.word_span,
                    ));
                    ObjectValue::empty()
                } else {
                    ObjectValue::single(Shape::Mesh(Arc::new(mesh)))
                }
            }
            (NodeKind::Mesh2, _) => {
                let (mesh, rest) = self.mesh2(node)?;
                modifiers = rest;
                ObjectValue::single(Shape::Mesh(mesh))
            }
            (_, View::MeshFile(file)) => {
                modifiers = &node.children;
                ObjectValue::single(Shape::Mesh(self.mesh_file(file)?))
            }
            (NodeKind::Union, _) => {
                if node.word == "composite" {
                    self.warn(Diagnostic::warning(
                        "`composite` is POV-Ray's old name of `union`: read as a union (POV-Ray warns too)",
                        node.word_span,
                    ));
                }
                // Members and the group's modifiers, in order (POV-Ray puts the modifiers last).
                modifiers = &[];
                let mut group = ObjectValue::empty();
                group.is_union = true;
                self.each_item(&node.children, &mut |ev, item| {
                    let m = if item.kind == NodeKind::LightSource {
                        let (mut light, looks) = ev.light(item)?;
                        if node.word == "light_group" {
                            // (Marked as the group's own: a light inside a member union is a
                            // global light, as in POV-Ray.)
                            light.group = Some(OWN_GROUP);
                        }
                        group.lights.push(light);
                        match looks {
                            Some(m) => m,
                            None => return Ok(()),
                        }
                    } else if !is_object(item.kind) {
                        return ev.object_modifier(&mut group, item, node);
                    } else {
                        ev.object(item)?
                    };
                    group.lights.extend(m.lights);
                    // The member's interiors stay distinct from the other members'; its parts
                    // without one of their own share the member's (POV-Ray shares one
                    // interior by reference among a union's members that have none).
                    let base = group.own_interiors;
                    for mut part in m.parts {
                        part.texture = part.texture.or_else(|| m.texture.clone());
                        part.interior_texture =
                            part.interior_texture.or_else(|| m.interior_texture.clone());
                        part.bounds.extend(m.bounds.iter().cloned());
                        if part.interior.is_some() {
                            part.interior_group += base;
                        } else if m.interior.is_some() {
                            part.interior = m.interior.clone();
                            part.interior_group = base + m.own_interiors;
                        }
                        group.parts.push(part);
                    }
                    group.own_interiors = base + m.own_interiors + 1;
                    Ok(())
                })?;
                if node.word == "light_group" {
                    self.light_group(&mut group);
                }
                group
            }
            (
                _,
                View::ObjectRef {
                    body: first,
                    modifiers: rest,
                },
            )
            | (
                _,
                View::LooksLike {
                    body: first,
                    modifiers: rest,
                },
            ) => {
                modifiers = rest;
                match first.kind {
                    NodeKind::LightSource => {
                        let (light, looks) = self.light(first)?;
                        let mut object = looks.unwrap_or_else(ObjectValue::empty);
                        object.lights.push(light);
                        object
                    }
                    NodeKind::IdentRef => match self.lookup(first)? {
                        Value::Object(o) => *o,
                        other => return Err(type_error("an object", &other, first.span)),
                    },
                    NodeKind::Unknown => return Err(self.unknown_item(first, "an object")),
                    _ => self.object(first)?,
                }
            }
            _ => return Err(crate::eval::malformed(node, "an object")),
        };
        self.each_item(modifiers, &mut |ev, m| {
            ev.object_modifier(&mut object, m, node)
        })?;
        // (Each object made is new to trace(), min_extent … : a modified copy is asked anew.)
        self.scene.next_object_id += 1;
        object.id = self.scene.next_object_id;
        Ok(object)
    }

    /// `trace(O, A, D [, N])`, `inside(O, P)`, `min_extent(O)`, `max_extent(O)`: the first hit
    /// of the ray from A along D (and its normal in N; zero vectors when missed), whether P
    /// is inside, the bounding box's corners.
    pub(in crate::eval) fn object_question(
        &mut self,
        name: &str,
        args: &[Expr],
        span: Span,
    ) -> Result<Value> {
        let (object, rest) = match (name, args) {
            ("trace", [object, rest @ ..]) if matches!(rest.len(), 2 | 3) => (object, rest),
            ("inside", [object, rest @ ..]) if rest.len() == 1 => (object, rest),
            ("min_extent" | "max_extent", [object]) => (object, &[][..]),
            _ => {
                let wanted = match name {
                    "trace" => {
                        "an object, a start point, a direction and optionally a vector for the normal"
                    }
                    "inside" => "an object and a point",
                    _ => "an object",
                };
                return Err(Diagnostic::error(format!("`{name}` takes {wanted}"), span));
            }
        };
        let query = self.object_query_of(object)?;
        Ok(match rest {
            [origin, direction, normal_to @ ..] => {
                let origin = self.vec3(origin)?;
                let direction_span = direction.span;
                let direction = self.vec3(direction)?;
                if direction.length_squared() == 0.0 {
                    return Err(Diagnostic::error(
                        "`trace`: the direction is the zero vector",
                        direction_span,
                    ));
                }
                let (point, normal) = query
                    .trace(origin, direction.normalize())
                    .unwrap_or((DVec3::ZERO, DVec3::ZERO));
                if let Some(n) = normal_to.first() {
                    let ExprKind::Ident(var, _) = &n.kind else {
                        return Err(Diagnostic::error(
                            "`trace` gives the normal to a variable named here",
                            n.span,
                        ));
                    };
                    self.set(var.clone(), Value::Vector(Vector::from_vec3(normal)));
                }
                Value::Vector(Vector::from_vec3(point))
            }
            [point] => {
                let p = self.vec3(point)?;
                Value::Float(if query.inside(p) { 1.0 } else { 0.0 })
            }
            _ => {
                let (lo, hi) = query.extent();
                Value::Vector(Vector::from_vec3(if name == "min_extent" {
                    lo
                } else {
                    hi
                }))
            }
        })
    }

    /// The object `e` names, ready for questions (made once per object; see `ObjectValue::id`).
    fn object_query_of(&mut self, e: &Expr) -> Result<Arc<dyn ir::ObjectQuery>> {
        /// Objects kept ready at once (a loop making and asking new objects does not pile them up).
        const KEPT: usize = 64;
        // (A declared object asked again is not copied to find its id.)
        let known = match &e.kind {
            ExprKind::Ident(_, slot) => match self.bound(*slot) {
                Some(Value::Object(o)) => self.scene.queries.get(&o.id).cloned(),
                _ => None,
            },
            _ => None,
        };
        if let Some(q) = known {
            return Ok(q);
        }
        let object = match self.eval(e)? {
            Value::Object(o) => o,
            other => return Err(type_error("an object", &other, e.span)),
        };
        if object.id != 0 {
            if let Some(q) = self.scene.queries.get(&object.id) {
                return Ok(Arc::clone(q));
            }
        }
        let parts = self.placed_parts(&object, e.span)?;
        let query: Arc<dyn ir::ObjectQuery> = Arc::from((self.scene.object_query)(parts));
        if object.id != 0 {
            if self.scene.queries.len() >= KEPT {
                self.scene.queries.clear();
            }
            self.scene.queries.insert(object.id, Arc::clone(&query));
        }
        Ok(query)
    }

    /// The parts of `object` placed in the world as the scene would hold them (for trace(),
    /// inside(), min_extent, max_extent).
    pub(in crate::eval) fn placed_parts(
        &mut self,
        object: &ObjectValue,
        span: Span,
    ) -> Result<Vec<ir::Object>> {
        let objects = std::mem::take(&mut self.scene.objects);
        let lights = std::mem::take(&mut self.scene.lights);
        let next_medium = self.scene.next_medium;
        let placed = self.place(object.clone(), span);
        let parts = std::mem::replace(&mut self.scene.objects, objects);
        self.scene.lights = lights;
        self.scene.next_medium = next_medium;
        placed.map(|()| parts)
    }

    /// Makes `group` a `light_group`: its lights light only its members (and those of the
    /// groups inside it, whose own lights stay theirs); its members see the lights outside
    /// every group only with `global_lights`.
    fn light_group(&mut self, group: &mut ObjectValue) {
        let id = self.scene.next_light_group;
        self.scene.next_light_group += 1;
        for light in group
            .lights
            .iter_mut()
            .filter(|l| l.group == Some(OWN_GROUP))
        {
            light.group = Some(id);
        }
        // (The members of a group inside see only that group's lights, as in POV-Ray.)
        for part in group.parts.iter_mut().filter(|p| p.light_group.is_none()) {
            part.light_group = Some(ir::LightGroup {
                groups: vec![id],
                global_lights: group.global_lights,
            });
        }
    }

    /// `isosurface { function {…} [contained_by {…}] settings… modifiers }`.
    fn isosurface(&mut self, node: &Node) -> Result<ObjectValue> {
        let mut iso = ir::Isosurface {
            function: std::sync::Arc::new(crate::func::Function::internal(
                crate::func::Internal::R,
            )),
            container: ir::Container::Box(DVec3::splat(-1.0), DVec3::splat(1.0)),
            threshold: 0.0,
            accuracy: 0.001,
            max_gradient: 1.1,
            closed: true,
            max_trace: 1,
        };
        let mut function = None;
        let mut modifiers: Vec<Node> = Vec::new();
        self.each_item(&node.children, &mut |ev, item| {
            match item.kind {
                NodeKind::Function => function = Some(ev.function(item)?),
                // (`open` among the modifiers reads as a flag.)
                NodeKind::Flag if item.word == "open" => iso.closed = false,
                NodeKind::ContainedBy => iso.container = ev.container(item)?,
                NodeKind::IsoSetting => {
                    let View::IsoSetting { values } = item.view() else {
                        return Err(crate::eval::malformed(item, "an isosurface setting"));
                    };
                    let word = item.word.as_str();
                    let takes = match word {
                        "open" | "all_intersections" => 0,
                        "evaluate" => 3,
                        _ => 1,
                    };
                    if let Some(extra) = values.get(takes..).and_then(<[Expr]>::first) {
                        return Err(Diagnostic::error(
                            format!("`{word}` takes {takes} value{}", if takes == 1 { "" } else { "s" }),
                            extra.span,
                        ));
                    }
                    match (word, values) {
                        ("threshold", [v]) => iso.threshold = ev.float(v)?,
                        ("accuracy", [v]) => iso.accuracy = ev.float(v)?,
                        ("max_gradient", [v]) => iso.max_gradient = ev.float(v)?,
                        ("max_trace", [v]) => iso.max_trace = ev.float(v)?.max(1.0) as u32,
                        ("all_intersections", []) => iso.max_trace = 10,
                        ("open", []) => iso.closed = false,
                        ("evaluate", _) => {
                            return Err(Diagnostic::error(
                                "unsupported: `evaluate` on an isosurface (trace keeps max_gradient fixed)",
                                item.word_span,
                            ));
                        }
                        _ => return Err(Diagnostic::error(format!("`{word}` needs a value"), item.word_span)),
                    }
                }
                _ => modifiers.push(item.clone()),
            }
            Ok(())
        })?;
        let Some(function) = function else {
            return Err(Diagnostic::error(
                "an isosurface needs its function { … }",
                node.word_span,
            ));
        };
        if function.params < 3 {
            return Err(Diagnostic::error(
                "an isosurface's function takes x, y and z (three parameters)",
                node.word_span,
            ));
        }
        if iso.accuracy <= 0.0 || iso.max_gradient <= 0.0 {
            return Err(Diagnostic::error(
                "an isosurface's accuracy and max_gradient must be above 0",
                node.word_span,
            ));
        }
        iso.function = function;
        let mut object = ObjectValue::single(Shape::Isosurface(Box::new(iso)));
        for m in &modifiers {
            self.object_modifier(&mut object, m, node)?;
        }
        Ok(object)
    }

    /// `contained_by { box {…} | sphere {…} }`.
    fn container(&mut self, contained_by: &Node) -> Result<ir::Container> {
        let View::ContainedBy { shape } = contained_by.view() else {
            return Err(crate::eval::malformed(contained_by, "contained_by"));
        };
        match shape.view() {
            View::Sphere { centre, radius, .. } => Ok(ir::Container::Sphere(
                self.vec3(centre)?,
                self.float(radius)?,
            )),
            View::Box { corner1, corner2 } => {
                let (a, b) = (self.vec3(corner1)?, self.vec3(corner2)?);
                Ok(ir::Container::Box(a.min(b), a.max(b)))
            }
            _ => Err(crate::eval::malformed(shape, "a box or a sphere")),
        }
    }

    /// `parametric { function {…} ×3 <u1, v1>, <u2, v2> [contained_by {…}] settings… modifiers }`.
    fn parametric(&mut self, node: &Node, uv_min: &Expr, uv_max: &Expr) -> Result<ObjectValue> {
        let mut functions = Vec::new();
        let mut container = ir::Container::Box(DVec3::splat(-1.0), DVec3::splat(1.0));
        let (mut accuracy, mut max_gradient, mut precompute) = (0.001, 1.0, None);
        let mut modifiers: Vec<Node> = Vec::new();
        let uv = |ev: &mut Self, e: &crate::syntax::Expr| -> Result<glam::DVec2> {
            match ev.eval(e)? {
                Value::Float(f) => Ok(glam::DVec2::splat(f)),
                Value::Vector(v) if v.len == 2 => Ok(glam::DVec2::new(v.c[0], v.c[1])),
                other => Err(crate::eval::lang::expr::type_error(
                    "a 2-D vector <u, v>",
                    &other,
                    e.span,
                )),
            }
        };
        let (a, b) = (uv(self, uv_min)?, uv(self, uv_max)?);
        self.each_item(&node.children, &mut |ev, item| {
            match item.kind {
                NodeKind::Function => functions.push(ev.function(item)?),
                NodeKind::ContainedBy => container = ev.container(item)?,
                NodeKind::IsoSetting => match (item.word.as_str(), item.view()) {
                    ("accuracy" | "max_gradient", View::IsoSetting { values: [v] }) => {
                        let v = ev.float(v)?;
                        if item.word == "accuracy" {
                            accuracy = v;
                        } else {
                            max_gradient = v;
                        }
                    }
                    ("precompute", View::IsoSetting { values: [depth, named @ ..] }) if named.len() <= 3 => {
                        let depth_span = depth.span;
                        let depth = ev.float(depth)?;
                        if !(1.0..=20.0).contains(&depth) {
                            return Err(Diagnostic::error("precompute's depth is 1 to 20", depth_span));
                        }
                        let mut axes = [false; 3];
                        for e in named {
                            match &e.kind {
                                crate::syntax::ExprKind::Ident(w, _) if w == "x" => axes[0] = true,
                                crate::syntax::ExprKind::Ident(w, _) if w == "y" => axes[1] = true,
                                crate::syntax::ExprKind::Ident(w, _) if w == "z" => axes[2] = true,
                                _ => return Err(Diagnostic::error("precompute names x, y and z", e.span)),
                            }
                        }
                        precompute = Some((depth as u32, axes));
                    }
                    _ => {
                        return Err(Diagnostic::error(
                            format!(
                                "`{}` does not belong in a parametric, or has the wrong number of values",
                                item.word
                            ),
                            item.word_span,
                        ));
                    }
                },
                _ => modifiers.push(item.clone()),
            }
            Ok(())
        })?;
        let [fx, fy, fz]: [std::sync::Arc<crate::func::Function>; 3] = functions
            .try_into()
            .map_err(|_| Diagnostic::error("a parametric takes three functions", node.word_span))?;
        if accuracy <= 0.0 || max_gradient <= 0.0 {
            return Err(Diagnostic::error(
                "a parametric's accuracy and max_gradient must be above 0",
                node.word_span,
            ));
        }
        let surface = ir::Parametric {
            functions: [fx, fy, fz],
            uv: (a.min(b), a.max(b)),
            container,
            accuracy,
            max_gradient,
            precompute,
        };
        let mut object = ObjectValue::single(Shape::Parametric(Box::new(surface)));
        for m in &modifiers {
            self.object_modifier(&mut object, m, node)?;
        }
        Ok(object)
    }

    /// `blob { … }`: its threshold and components (which come before its modifiers, as in
    /// POV-Ray), then the modifiers.
    fn blob(&mut self, node: &Node) -> Result<ObjectValue> {
        let mut blob = ir::Blob {
            threshold: 1.0,
            components: Vec::new(),
        };
        let mut modifiers: Vec<Node> = Vec::new();
        self.each_item(&node.children, &mut |ev, item| {
            let component = matches!(
                item.kind,
                NodeKind::Sphere | NodeKind::Cylinder | NodeKind::BlobComponent | NodeKind::BlobThreshold
            ) || item.kind == NodeKind::IsoSetting && item.word == "threshold";
            if component && !modifiers.is_empty() {
                return Err(Diagnostic::error(
                    "a blob's components and threshold come before its modifiers",
                    item.word_span,
                ));
            }
            match (item.kind, item.view()) {
                (_, View::BlobThreshold(threshold)) => blob.threshold = ev.float(threshold)?,
                (_, View::BlobComponent { strength, radius, centre }) => {
                    let strength = ev.float(strength)?;
                    let radius = ev.float(radius)?;
                    let centre = ev.vec3(centre)?;
                    blob.components.push(ir::BlobComponent {
                        reach: ir::BlobReach::Sphere(centre),
                        radius,
                        strength,
                        transform: None,
                        texture: None,
                    });
                }
                (_, view @ (View::Sphere { strength, .. } | View::Cylinder { strength, .. })) => {
                    let Some(strength) = strength else {
                        return Err(Diagnostic::error(
                            format!("a blob's {} takes a strength after its radius", item.word),
                            item.span,
                        ));
                    };
                    let strength = ev.float(strength)?;
                    let (reach, radius) = match view {
                        View::Cylinder { base, cap, radius, .. } => {
                            let (a, b) = (ev.vec3(base)?, ev.vec3(cap)?);
                            if (b - a).length() < 1e-10 {
                                return Err(Diagnostic::error(
                                    "this blob cylinder's two ends are the same point",
                                    item.word_span,
                                ));
                            }
                            (ir::BlobReach::Cylinder(a, b), radius)
                        }
                        View::Sphere { centre, radius, .. } => {
                            (ir::BlobReach::Sphere(ev.vec3(centre)?), radius)
                        }
                        _ => return Err(crate::eval::malformed(item, "a blob component")),
                    };
                    let radius = ev.float(radius)?;
                    let mut transform: Option<Transform> = None;
                    let mut texture: Option<Texture> = None;
                    ev.each_item(&item.children, &mut |ev, m| {
                        if Self::is_transform(m) {
                            let t = ev.transform(m)?;
                            transform = compose(transform, t);
                            // (A component's texture moves with the component.)
                            if let Some(texture) = &mut texture {
                                texture.transform(t);
                            }
                            return Ok(());
                        }
                        match m.kind {
                            NodeKind::Texture => {
                                let t = ev.texture(m)?;
                                texture = Some(match texture.take() {
                                    // A second texture is a layer on top, as on objects.
                                    Some(below) => crate::eval::build::material::layer(t, below),
                                    None => t,
                                });
                                Ok(())
                            }
                            NodeKind::Pigment | NodeKind::Normal | NodeKind::Finish => {
                                let mut t = texture.take().unwrap_or_else(|| ev.scene.default_texture.clone());
                                match m.kind {
                                    NodeKind::Pigment => t.pigment = ev.pigment(m, t.pigment.clone())?,
                                    NodeKind::Normal => t.normal = Some(Box::new(ev.normal(m, t.normal.take())?)),
                                    _ => t.finish = ev.shared_finish_block(m, &t.finish)?,
                                }
                                texture = Some(t);
                                Ok(())
                            }
                            _ => Err(Diagnostic::error(
                                format!(
                                    "`{}` does not belong on a blob component (it takes transformations and a texture)",
                                    m.word
                                ),
                                m.word_span,
                            )),
                        }
                    })?;
                    blob.components.push(ir::BlobComponent {
                        reach,
                        radius,
                        strength,
                        transform: transform.map(|t| t.matrix),
                        texture: texture.map(Box::new),
                    });
                }
                _ if is_object(item.kind) => {
                    return Err(Diagnostic::error(
                        format!("a blob's components are spheres and cylinders, not `{}`", item.word),
                        item.word_span,
                    ));
                }
                _ => modifiers.push(item.clone()),
            }
            Ok(())
        })?;
        if blob.components.is_empty() {
            return Err(Diagnostic::error(
                "a blob needs at least one component",
                node.word_span,
            ));
        }
        let mut object = ObjectValue::single(Shape::Blob(Box::new(blob)));
        for m in &modifiers {
            self.object_modifier(&mut object, m, node)?;
        }
        Ok(object)
    }

    fn nonzero(&mut self, e: &Expr, what: &str) -> Result<DVec3> {
        let v = self.vec3(e)?;
        if v.length_squared() == 0.0 {
            return Err(Diagnostic::error(
                format!("{what} is the zero vector"),
                e.span,
            ));
        }
        Ok(v)
    }

    /// Whether a flag (`hollow`, `no_shadow` …) is on: without a value, or with one above
    /// zero, as POV-Ray reads it (the grammar reads `on`/`off`/`true`/`false`/`yes`/`no` as 1
    /// and 0; any float expression may stand there).
    fn flag_on(&mut self, flag: &Node) -> Result<bool> {
        Ok(match flag.view() {
            View::Flag { on: Some(e) } => self.float(e)? > 0.0,
            _ => true,
        })
    }

    /// One modifier `m` of object statement `owner`.
    fn object_modifier(&mut self, object: &mut ObjectValue, m: &Node, owner: &Node) -> Result<()> {
        let is_cone = matches!(owner.kind, NodeKind::Cylinder | NodeKind::Cone);
        let on = m.kind != NodeKind::Flag || self.flag_on(m)?;
        match m.kind {
            NodeKind::Material => {
                let v = self.material(m)?;
                if let Some(texture) = v.texture {
                    self.set_texture(object, texture)?;
                }
                if let Some(texture) = v.interior_texture {
                    set_interior_texture(object, texture);
                }
                if v.interior.is_some() {
                    object.interior = v.interior;
                }
            }
            NodeKind::UvMapping => {
                if object.texture.is_some() {
                    return Err(Diagnostic::error(
                        "`uv_mapping` must come before the object's texture",
                        m.span,
                    ));
                }
                object.uv_mapping = true;
            }
            NodeKind::Texture => {
                let mut texture = self.texture(m)?;
                if object.uv_mapping {
                    texture = self.uv_texture(texture);
                }
                self.set_texture(object, texture)?;
            }
            NodeKind::InteriorTexture => {
                let texture = self.texture(m)?;
                set_interior_texture(object, texture);
            }

            NodeKind::Pigment | NodeKind::Normal | NodeKind::Finish => {
                let mut texture = match object.texture.take() {
                    Some(t) => t,
                    None if object.uv_mapping => {
                        self.uv_texture(self.scene.default_texture.clone())
                    }
                    None => self.scene.default_texture.clone(),
                };
                let target = crate::eval::build::material::uv_entry(&mut texture);
                match m.kind {
                    NodeKind::Pigment => {
                        target.pigment = self.pigment(m, target.pigment.clone())?
                    }
                    NodeKind::Normal => {
                        target.normal = Some(Box::new(self.normal(m, target.normal.take())?))
                    }
                    _ => target.finish = self.shared_finish_block(m, &target.finish)?,
                }
                object.texture = Some(texture);
            }
            NodeKind::BoundedBy => {
                self.each_item(&m.children, &mut |ev, item| {
                    if !is_object(item.kind) {
                        return Err(ev.unknown_item(item, "bounded_by"));
                    }
                    for part in ev.object(item)?.parts {
                        object.bounds.push(ir::Bound {
                            shape: part.shape,
                            transform: part.transform.map(Box::new),
                        });
                    }
                    Ok(())
                })?;
            }
            NodeKind::Interior => {
                let base = object.interior.take().unwrap_or_default();
                object.interior = Some(self.interior(m, base)?);
            }
            NodeKind::ObjectRadiosity => {
                if let Some(v) = self.radiosity_importance(m, "an object's radiosity")? {
                    object.parts.iter_mut().for_each(|p| p.importance = Some(v));
                }
            }
            NodeKind::Flag if m.word == "hollow" => {
                // On one object the last `hollow` counts; a group's goes to the members that
                // have none of their own.
                for part in &mut object.parts {
                    if object.is_union {
                        part.hollow.get_or_insert(on);
                    } else {
                        part.hollow = Some(on);
                    }
                }
            }
            // `no_shadow false` …: the flag is not set.
            NodeKind::Flag if !on => {}
            // A shape's own words (`ttf`, `conic_sweep`, `open` of a prism…): read by the
            // shape table.
            NodeKind::Flag
                if owner.kind == NodeKind::Shape
                    && crate::eval::build::shapes::takes(&owner.word, &m.word) => {}
            // A shape's values: read by the shape table.
            NodeKind::Value if owner.kind == NodeKind::Shape => {}
            // A height field's function image: read by the shape table.
            NodeKind::FunctionImage if owner.word == "height_field" => {}
            NodeKind::Flag => match m.word.as_str() {
                "no_shadow" => object.parts.iter_mut().for_each(|p| p.no_shadow = true),
                "no_image" => object
                    .parts
                    .iter_mut()
                    .for_each(|p| p.sight.no_image = true),
                "no_reflection" => object
                    .parts
                    .iter_mut()
                    .for_each(|p| p.sight.no_reflection = true),
                "double_illuminate" => object
                    .parts
                    .iter_mut()
                    .for_each(|p| p.sight.double_illuminate = true),
                "no_radiosity" => object
                    .parts
                    .iter_mut()
                    .for_each(|p| p.sight.no_radiosity = true),
                "global_lights" if owner.word == "light_group" => object.global_lights = true,
                "global_lights" => {
                    return Err(Diagnostic::error(
                        "`global_lights` applies only to a light_group",
                        m.word_span,
                    ));
                }
                "inverse" => object.parts.iter_mut().for_each(|p| p.inverse = !p.inverse),
                // `sturm` picks POV-Ray's slower root solver; trace's torus solver is always
                // robust.
                "sturm" => {}
                // `hierarchy` switches POV-Ray's bounding tree inside a blob, mesh or height
                // field: speed only, nothing to draw; on another shape POV-Ray refuses it.
                "hierarchy"
                    if matches!(
                        owner.word.as_str(),
                        "blob" | "mesh" | "mesh2" | "height_field" | "object"
                    ) => {}
                "hierarchy" => {
                    return Err(Diagnostic::error(
                        "`hierarchy` applies only to blob, mesh, mesh2 and height_field",
                        m.word_span,
                    ));
                }
                "open" if is_cone => {}
                "open" => {
                    return Err(Diagnostic::error(
                        "`open` applies only to cylinder and cone",
                        m.word_span,
                    ));
                }
                other => return Err(self.unknown_word(other, m.word_span)),
            },
            _ if Self::is_transform(m) => {
                let t = self.transform(m)?;
                object.transform(t, m.kind == NodeKind::Scale);
            }
            NodeKind::ColourItem => {
                // POV-Ray's quick colour: used only by its low-quality previews (+Q5 and
                // below), ignored at the quality trace renders (checked against POV-Ray).
                if let View::ColourItem(colour) = m.view() {
                    self.eval(colour)?;
                }
                self.warn(Diagnostic::warning(
                    "a colour among an object's items is POV-Ray's quick colour (for low-quality previews only): ignored; use pigment { … } to colour the object",
                    m.span,
                ));
            }
            _ => return Err(self.unknown_item(m, "an object")),
        }
        Ok(())
    }

    /// A texture given to an object by `texture {…}` or `material {…}`.
    fn set_texture(&mut self, object: &mut ObjectValue, texture: ir::Texture) -> Result<()> {
        // A second texture is layered on top of the first, as in POV-Ray.
        object.texture = Some(match object.texture.take() {
            Some(below) => crate::eval::build::material::layer(texture, below),
            None => texture,
        });
        Ok(())
    }

    /// Adds the object's parts (and the lights it holds) to the scene. Transformations that
    /// overflowed together (`scale 1e200 scale 1e200`) are an error at `span`.
    pub(in crate::eval) fn place(&mut self, mut object: ObjectValue, span: Span) -> Result<()> {
        let usable = |t: &ir::Transform| t.matrix.is_finite() && t.inverse().matrix.is_finite();
        if !object
            .parts
            .iter()
            .filter_map(|p| p.transform.as_ref())
            .all(usable)
        {
            return Err(Diagnostic::error(
                "this object's transformations overflow (scaled or moved beyond what a number can hold) or flatten it",
                span,
            ));
        }
        // Fresh light groups for this instance: two `object { G }` of one declared
        // light_group each light their own members, as in POV-Ray.
        let mut fresh: Vec<(u32, u32)> = Vec::new();
        let mut renumber = |id: u32, next: &mut u32| match fresh.iter().find(|(old, _)| *old == id)
        {
            Some(&(_, new)) => new,
            None => {
                let new = *next;
                *next += 1;
                fresh.push((id, new));
                new
            }
        };
        for light in &mut object.lights {
            if let Some(g) = light.group.filter(|&g| g != OWN_GROUP) {
                light.group = Some(renumber(g, &mut self.scene.next_light_group));
            }
        }
        for part in &mut object.parts {
            if let Some(group) = &mut part.light_group {
                for g in &mut group.groups {
                    *g = renumber(*g, &mut self.scene.next_light_group);
                }
            }
        }
        self.scene.lights.append(&mut object.lights);
        // Fresh media for this instance (two `object { U }` of one declared union do not
        // share interiors: POV-Ray copies them with the object).
        let base = self.scene.next_medium;
        self.scene.next_medium = base.saturating_add(object.own_interiors).saturating_add(1);
        for (member, mut part) in object.parts.into_iter().enumerate() {
            if let (Some(world), Some(t), Shape::Mesh(mesh)) =
                (part.vertex_normals, &part.transform, &mut part.shape)
            {
                // Object-space normals that the transform takes to the tracked ones: the
                // linear interpolation then runs over those, as in POV-Ray.
                let linear_t = DMat3::from_mat4(t.matrix).transpose();
                Arc::make_mut(mesh).normals =
                    world.iter().map(|n| (linear_t * *n).as_vec3()).collect();
            }
            let medium = match part.interior {
                Some(_) => base + part.interior_group,
                None => base + object.own_interiors,
            };
            let texture = part
                .texture
                .or_else(|| object.texture.clone())
                .unwrap_or_else(|| self.scene.default_texture.clone());
            let interior_texture = part
                .interior_texture
                .or_else(|| object.interior_texture.clone());
            // A plain texture's finish gives the interior POV-Ray's old items written there
            // (its `ior` if given, its `refraction` always: POV-Ray's Post_Process).
            let mut own = part.interior.or_else(|| object.interior.clone());
            let finish = &texture.finish;
            let legacy_caustics = finish.legacy_caustics.filter(|c| *c >= 0.0);
            if texture.map.is_none()
                && (own.is_some()
                    || finish.legacy_ior.is_some()
                    || finish.legacy_refraction != 1.0
                    || legacy_caustics.is_some())
            {
                let mut i = own.unwrap_or_default();
                if let Some(ior) = finish.legacy_ior {
                    // (With the finish's ior comes the finish's dispersion, which is 1.)
                    i.ior = ior;
                    i.ior_given = true;
                    i.dispersion = 1.0;
                }
                i.refraction = finish.legacy_refraction;
                i.caustics = legacy_caustics.unwrap_or(i.caustics);
                own = Some(i);
            }
            // An interior given no ior takes the air's, and the air's dispersion with it (POV-Ray's
            // Post_Process).
            if let Some(i) = own.as_mut().filter(|i| !i.ior_given) {
                i.dispersion = 1.0;
            }
            // (Objects without an interior share one default interior.)
            let interior = match own {
                Some(interior) => self.shared_interior(interior),
                None => std::sync::Arc::clone(&self.scene.default_interior),
            };
            let mut shapes = part.bounds;
            shapes.extend(object.bounds.iter().cloned());
            // POV-Ray keeps the bounding shapes of unions, polynomials and quadrics without
            // bounds of their own; of other shapes only the bound's box stays.
            let test_rays = object.is_union
                || match &part.shape {
                    Shape::Polynomial(_) => true,
                    Shape::Quadric(q) => q.mixed != DVec3::ZERO || q.square.min_element() <= 0.0,
                    _ => false,
                };
            let bounds = (!shapes.is_empty()).then(|| Arc::new(ir::Bounds { shapes, test_rays }));
            let (sight, light_group, importance) = (part.sight, part.light_group, part.importance);
            let extras = (interior_texture.is_some()
                || bounds.is_some()
                || sight != ir::Sight::default()
                || light_group.is_some()
                || importance.is_some())
            .then(|| {
                Box::new(ir::ObjectExtras {
                    interior_texture,
                    bounds,
                    sight,
                    light_group,
                    importance,
                })
            });
            self.scene.objects.push(ir::Object {
                extras,
                shape: part.shape,
                transform: part.transform.map(Box::new),
                texture,
                interior,
                no_shadow: part.no_shadow,
                inverse: part.inverse,
                hollow: part.hollow.unwrap_or(false),
                member: member as u32,
                medium,
            });
        }
        Ok(())
    }

    /// Appends a `triangle` or `smooth_triangle` node to a mesh (a degenerate one is dropped
    /// with a warning, as POV-Ray does).
    /// (`in_mesh`: a mesh's member, flat when its three normals are equal and kept whatever
    /// their sides; a stand-alone smooth triangle keeps equal normals smooth and is dropped
    /// when they straddle its face, as POV-Ray does.)
    fn add_triangle(&mut self, mesh: &mut Mesh, node: &Node, in_mesh: bool) -> Result<()> {
        let (p, normals) = match node.view() {
            View::Triangle { a, b, c } => ([self.vec3(a)?, self.vec3(b)?, self.vec3(c)?], None),
            View::SmoothTriangle {
                a,
                a_normal,
                b,
                b_normal,
                c,
                c_normal,
            } => {
                let (a, na) = (self.vec3(a)?, self.vec3(a_normal)?);
                let (b, nb) = (self.vec3(b)?, self.vec3(b_normal)?);
                let (c, nc) = (self.vec3(c)?, self.vec3(c_normal)?);
                ([a, b, c], Some([na, nb, nc]))
            }
            _ => return Err(crate::eval::malformed(node, "a triangle")),
        };
        let Some(normal_indices) =
            self.triangle_normals(mesh, &p, normals, in_mesh, node.word_span)
        else {
            return Ok(());
        };
        let base = mesh.vertices.len() as u32;
        mesh.vertices.extend(p.iter().map(|v| v.as_vec3()));
        mesh.triangles.push([base, base + 1, base + 2]);
        // `uv_vectors UV1, UV2, UV3`; once any triangle has them, the others are at (0, 0).
        let uv = node
            .children
            .iter()
            .find(|c| c.kind == NodeKind::TriangleUv);
        if uv.is_some() || !mesh.uv_indices.is_empty() {
            let origin = |mesh: &mut Mesh| {
                let i = mesh.uvs.iter().position(|v| *v == DVec2::ZERO);
                i.unwrap_or_else(|| {
                    mesh.uvs.push(DVec2::ZERO);
                    mesh.uvs.len() - 1
                }) as u32
            };
            if mesh.uv_indices.len() + 1 < mesh.triangles.len() {
                let zero = origin(mesh);
                mesh.uv_indices.resize(mesh.triangles.len() - 1, [zero; 3]);
            }
            let corners = match uv {
                Some(uv) => {
                    let View::TriangleUv { a, b, c } = uv.view() else {
                        return Err(crate::eval::malformed(uv, "uv_vectors"));
                    };
                    let base = mesh.uvs.len() as u32;
                    for e in [a, b, c] {
                        let v = self.uv(e)?;
                        mesh.uvs.push(v);
                    }
                    [base, base + 1, base + 2]
                }
                None => [origin(mesh); 3],
            };
            mesh.uv_indices.push(corners);
        }
        if normal_indices != FLAT || !mesh.normal_indices.is_empty() {
            // Keep normal_indices parallel to triangles once any triangle is smooth.
            mesh.normal_indices.resize(mesh.triangles.len() - 1, FLAT);
            mesh.normal_indices.push(normal_indices);
        }
        Ok(())
    }

    /// Checks a triangle and stores its normals: `Some(FLAT)` for a flat triangle, `Some(indices)`
    /// for a smooth one, `None` (with a warning) for a degenerate one.
    fn triangle_normals(
        &mut self,
        mesh: &mut Mesh,
        p: &[DVec3; 3],
        normals: Option<[DVec3; 3]>,
        in_mesh: bool,
        span: Span,
    ) -> Option<[u32; 3]> {
        let ng = (p[1] - p[0]).cross(p[2] - p[0]);
        if ng.length_squared() == 0.0 {
            self.warn(Diagnostic::warning(
                "degenerate triangle (zero area) is not rendered",
                span,
            ));
            return None;
        }
        let Some(n) = normals else { return Some(FLAT) };
        match smooth_normals(ng, &n, in_mesh) {
            SmoothNormals::Flat => Some(FLAT),
            SmoothNormals::Degenerate => {
                self.warn(Diagnostic::warning(
                    "degenerate smooth_triangle: a zero normal, or normals on both sides of the face (POV-Ray drops it; in a mesh it would be kept)",
                    span,
                ));
                None
            }
            SmoothNormals::Smooth(unit) => {
                let base = mesh.normals.len() as u32;
                mesh.normals.extend(unit.iter().map(|v| v.as_vec3()));
                Some([base, base + 1, base + 2])
            }
        }
    }

    fn inside_vector<'n>(&mut self, mesh: &mut Mesh, rest: &'n [Node]) -> Result<&'n [Node]> {
        match rest {
            [iv, after @ ..] if iv.kind == NodeKind::InsideVector => {
                let View::InsideVector(direction) = iv.view() else {
                    return Err(crate::eval::malformed(iv, "inside_vector"));
                };
                mesh.inside_vector = Some(self.nonzero(direction, "inside_vector")?);
                Ok(after)
            }
            _ => Ok(rest),
        }
    }

    /// `mesh2 { vertex_vectors normal_vectors face_indices normal_indices inside_vector }`.
    /// A mesh of big lists read by the fast lane is made once while those lists are the
    /// same ones (`trace watch`: a save that leaves a 1M-triangle mesh's text alone does not
    /// make its mesh again).
    fn mesh2<'n>(&mut self, node: &'n Node) -> Result<(Arc<Mesh>, &'n [Node])> {
        let View::Mesh2(parts) = node.view() else {
            return Err(crate::eval::malformed(node, "a mesh2"));
        };
        // The mesh is a function of its lists alone (and its inside vector) when they all
        // came from the fast lane and it has no textures or uv vectors.
        let mut inside = Mesh::default();
        let rest = self.inside_vector(&mut inside, parts.rest)?;
        fn bulk(n: Option<&Node>) -> Option<Option<&crate::syntax::bulk::BulkList>> {
            match n.map(list_view).transpose() {
                Ok(Some(List::Bulk(list))) => Some(Some(list)),
                Ok(None) => Some(None),
                _ => None,
            }
        }
        let lists: Option<Vec<Option<&crate::syntax::bulk::BulkList>>> = [
            Some(parts.vertices),
            parts.normals,
            Some(parts.faces),
            parts.normal_indices,
            parts.uv_indices,
        ]
        .into_iter()
        .map(bulk)
        .collect();
        let lists = lists.filter(|_| parts.textures.is_none() && parts.uvs.is_none());
        let words: Vec<u64> = match inside.inside_vector {
            Some(v) => [v.x, v.y, v.z].map(|c| c.to_bits()).to_vec(),
            None => Vec::new(),
        };
        if let Some(lists) = &lists {
            if let Some(made) = (self.options.lists).derived::<(Arc<Mesh>, usize)>(lists, &words) {
                self.degenerate_warning(made.1, node);
                return Ok((Arc::clone(&made.0), rest));
            }
        }
        let (mut mesh, degenerate) = self.mesh2_made(node, &parts)?;
        mesh.inside_vector = inside.inside_vector;
        self.degenerate_warning(degenerate, node);
        let mesh = Arc::new(mesh);
        if let Some(lists) = &lists {
            let made = Arc::new((Arc::clone(&mesh), degenerate));
            self.options.lists.keep_derived(lists, &words, made);
        }
        Ok((mesh, rest))
    }

    fn degenerate_warning(&mut self, degenerate: usize, node: &Node) {
        if degenerate > 0 {
            self.warn(Diagnostic::warning(
                format!("mesh2: {degenerate} zero-area triangles are not rendered (as in POV-Ray)"),
                node.word_span,
            ));
        }
    }

    /// A mesh2's mesh (without its inside vector) and how many zero-area triangles it
    /// dropped.
    fn mesh2_made(
        &mut self,
        node: &Node,
        parts: &crate::syntax::view::Mesh2Parts,
    ) -> Result<(Mesh, usize)> {
        let (vertex_node, normal_node, uv_node) = (parts.vertices, parts.normals, parts.uvs);
        let (texture_node, face_node) = (parts.textures, parts.faces);
        let (normal_index_node, uv_index_node) = (parts.normal_indices, parts.uv_indices);
        let vertices = self.vector_list(vertex_node)?;
        let normals = match normal_node {
            Some(n) => self.vector_list(n)?,
            None => Vec::new(),
        };
        let (faces, face_textures, textures) = match texture_node {
            Some(list) => {
                let textures = self.texture_list(list)?;
                let (faces, face_textures) =
                    self.faces_with_textures(face_node, vertices.len(), textures.len())?;
                (faces, face_textures, textures)
            }
            None => (
                self.index_list(face_node, vertices.len())?,
                Vec::new(),
                Vec::new(),
            ),
        };
        let normal_faces = match normal_index_node {
            Some(n) => self.index_list(n, normals.len())?,
            // Without normal_indices, as many normals as vertices reuse the face indices.
            None if !normals.is_empty() && normals.len() == vertices.len() => faces.clone(),
            None if !normals.is_empty() => {
                return Err(Diagnostic::error(
                    "normal_vectors needs normal_indices unless it has one normal per vertex",
                    normal_node.map_or(node.word_span, |n| n.word_span),
                ));
            }
            None => Vec::new(),
        };
        if !normal_faces.is_empty() && normal_faces.len() != faces.len() {
            return Err(Diagnostic::error(
                format!(
                    "normal_indices has {} entries, face_indices {}",
                    normal_faces.len(),
                    faces.len()
                ),
                normal_index_node.map_or(node.word_span, |n| n.word_span),
            ));
        }
        // `uv_vectors` and `uv_indices` (without indices, one uv per vertex takes the face
        // indices, and a single uv serves every corner, as in POV-Ray).
        let uvs = match uv_node {
            Some(n) => {
                let entries = self.list_entries(n)?;
                let mut uvs = Vec::with_capacity(entries.len());
                for e in entries {
                    uvs.push(self.uv(e)?);
                }
                uvs
            }
            None => Vec::new(),
        };
        let uv_faces = match uv_index_node {
            Some(n) => {
                let list = self.index_list(n, uvs.len())?;
                if list.len() != faces.len() {
                    return Err(Diagnostic::error(
                        "the number of uv indices must equal the number of faces",
                        n.word_span,
                    ));
                }
                list
            }
            None if uvs.is_empty() => Vec::new(),
            None if uvs.len() == vertices.len() => faces.clone(),
            None if uvs.len() == 1 => vec![[0; 3]; faces.len()],
            None => {
                return Err(Diagnostic::error(
                    "mesh2 needs uv_indices unless it has one uv per vertex",
                    uv_node.map_or(node.word_span, |n| n.word_span),
                ));
            }
        };
        let (mut mesh, degenerate) = assemble_mesh(
            &vertices,
            &normals,
            &faces,
            &normal_faces,
            &uv_faces,
            &face_textures,
        );
        mesh.uvs = uvs;
        if mesh
            .face_textures
            .iter()
            .any(|f| f.iter().any(|&t| t != ir::OWN_TEXTURE))
        {
            mesh.textures = textures;
        } else {
            mesh.face_textures.clear();
        }
        if mesh.triangles.is_empty() {
            return Err(Diagnostic::error(
                "mesh2 has no renderable triangle",
                node.word_span,
            ));
        }
        Ok((mesh, degenerate))
    }

    /// `mesh_file { "name.obj" }`: the file's mesh, read once however often it is used.
    fn mesh_file(&mut self, file_expr: &Expr) -> Result<Arc<Mesh>> {
        let file = self.string(file_expr)?;
        let path = self.find_file(&file, "mesh file", file_expr.span)?;
        if let Some(mesh) = self.scene.mesh_files.get(&path) {
            return Ok(Arc::clone(mesh));
        }
        let data = crate::meshfile::read(&path).map_err(|e| {
            let line = e.location.map(|l| format!(":{l}")).unwrap_or_default();
            Diagnostic::error(
                format!("cannot read mesh file {file}{line}: {}", e.message),
                file_expr.span,
            )
        })?;
        let (mesh, degenerate) = assemble_mesh(
            &data.vertices,
            &data.normals,
            &data.faces,
            &data.normal_faces,
            &[],
            &[],
        );
        if degenerate > 0 {
            self.warn(Diagnostic::warning(
                format!(
                    "{file}: {degenerate} zero-area triangles are not rendered (as POV-Ray would not render them in the converted mesh2)"
                ),
                file_expr.span,
            ));
        }
        if mesh.triangles.is_empty() {
            return Err(Diagnostic::error(
                format!("{file} has no renderable triangle"),
                file_expr.span,
            ));
        }
        let mesh = Arc::new(mesh);
        self.scene.mesh_files.insert(path, Arc::clone(&mesh));
        Ok(mesh)
    }

    /// The entries of `vertex_vectors { n, V… }`, checking the count.
    fn vector_list(&mut self, node: &Node) -> Result<Vec<DVec3>> {
        if let List::Bulk(list) = list_view(node)? {
            check_bulk_count(node, list)?;
            return Ok(list.values.iter().map(|v| DVec3::from_array(*v)).collect());
        }
        let entries = self.list_entries(node)?;
        let mut out = Vec::with_capacity(entries.len());
        for e in entries {
            out.push(self.vec3(e)?);
        }
        Ok(out)
    }

    /// The entries of `face_indices { n, <a,b,c>… }`, truncated to integers and range-checked.
    fn index_list(&mut self, node: &Node, limit: usize) -> Result<Vec<[u32; 3]>> {
        if let List::Bulk(list) = list_view(node)? {
            check_bulk_count(node, list)?;
            let mut out = Vec::with_capacity(list.values.len());
            for (k, v) in list.values.iter().enumerate() {
                let mut face = [0u32; 3];
                for (slot, &c) in face.iter_mut().zip(v) {
                    // (Truncated toward zero: in range exactly when -1 < c < limit; the cast
                    // truncates, without a call to trunc for each of millions of indices.)
                    if !(c > -1.0 && c < limit as f64) {
                        let (start, end) = list.span(k);
                        let span = Span::new(node.span.file, start as usize, end as usize);
                        return Err(Diagnostic::error(
                            format!("index {} is out of range (0..{limit})", c.trunc()),
                            span,
                        ));
                    }
                    *slot = c as u32;
                }
                out.push(face);
            }
            return Ok(out);
        }
        let entries = self.list_entries(node)?;
        let mut out = Vec::with_capacity(entries.len());
        for e in entries {
            let v = match self.eval(e)? {
                Value::Vector(v) if v.len == 3 => v,
                Value::Float(_) => {
                    return Err(Diagnostic::error(
                        "unsupported: per-face texture indices (texture_list is not supported by trace yet)",
                        e.span,
                    ));
                }
                other => return Err(type_error("a vector <a, b, c> of indices", &other, e.span)),
            };
            let mut face = [0u32; 3];
            for (slot, &c) in face.iter_mut().zip(&v.c[..3]) {
                let i = c.trunc();
                if !(i >= 0.0 && (i as usize) < limit) {
                    return Err(Diagnostic::error(
                        format!("index {i} is out of range (0..{limit})"),
                        e.span,
                    ));
                }
                *slot = i as u32;
            }
            out.push(face);
        }
        Ok(out)
    }

    /// `texture_list { N, texture {…} … }`.
    fn texture_list(&mut self, node: &Node) -> Result<Vec<ir::Texture>> {
        let View::TextureList(count) = node.view() else {
            return Err(crate::eval::malformed(node, "a texture_list"));
        };
        let n = self.float(count)?;
        let mut textures = Vec::new();
        self.each_item(&node.children, &mut |ev, item| {
            if item.kind != NodeKind::Texture {
                return Err(ev.unknown_item(item, "a texture_list"));
            }
            textures.push(ev.texture(item)?);
            Ok(())
        })?;
        if n.trunc() != textures.len() as f64 {
            return Err(Diagnostic::error(
                format!(
                    "`texture_list` announces {n} textures but lists {}",
                    textures.len()
                ),
                count.span,
            ));
        }
        Ok(textures)
    }

    /// A mesh2's `face_indices { N, <a, b, c> [, t [, t2, t3]] … }` after a texture_list:
    /// each face's vertex indices and its corners' textures (one for the face, or one per
    /// corner; none: the object's texture).
    fn faces_with_textures(
        &mut self,
        node: &Node,
        limit: usize,
        textures: usize,
    ) -> Result<(Faces, Faces)> {
        let (count, entries) = match list_view(node)? {
            List::Bulk(_) => {
                let faces = self.index_list(node, limit)?;
                let own = vec![[ir::OWN_TEXTURE; 3]; faces.len()];
                return Ok((faces, own));
            }
            List::Entries { count, entries } => (count, entries),
        };
        let n = self.float(count)?;
        let (mut faces, mut face_textures) = (Vec::new(), Vec::new());
        let mut pending: Vec<(u32, Span)> = Vec::new();
        let close = |faces: &Vec<[u32; 3]>,
                     face_textures: &mut Vec<[u32; 3]>,
                     pending: &mut Vec<(u32, Span)>| {
            if faces.len() > face_textures.len() {
                face_textures.push(match pending.as_slice() {
                    [] => [ir::OWN_TEXTURE; 3],
                    [(t, _)] => [*t; 3],
                    [(a, _), (b, _), (c, _)] => [*a, *b, *c],
                    [.., (_, span)] => {
                        return Err(Diagnostic::error(
                            "a face takes one texture index or three",
                            *span,
                        ));
                    }
                });
            }
            pending.clear();
            Ok(())
        };
        for e in entries {
            match self.eval(e)? {
                Value::Vector(v) if v.len == 3 => {
                    close(&faces, &mut face_textures, &mut pending)?;
                    let mut face = [0u32; 3];
                    for (slot, &c) in face.iter_mut().zip(&v.c[..3]) {
                        let i = c.trunc();
                        if !(i >= 0.0 && (i as usize) < limit) {
                            return Err(Diagnostic::error(
                                format!("index {i} is out of range (0..{limit})"),
                                e.span,
                            ));
                        }
                        *slot = i as u32;
                    }
                    faces.push(face);
                }
                Value::Float(t) if !faces.is_empty() => {
                    let t = t.trunc();
                    if !(t >= 0.0 && (t as usize) < textures) {
                        return Err(Diagnostic::error(
                            format!("texture index {t} is out of range (0..{textures})"),
                            e.span,
                        ));
                    }
                    pending.push((t as u32, e.span));
                }
                other => return Err(type_error("a vector <a, b, c> of indices", &other, e.span)),
            }
        }
        close(&faces, &mut face_textures, &mut pending)?;
        if n.trunc() != faces.len() as f64 {
            return Err(Diagnostic::error(
                format!(
                    "`face_indices` announces {n} entries but lists {}",
                    faces.len()
                ),
                count.span,
            ));
        }
        Ok((faces, face_textures))
    }

    /// A list's entries (not read by a fast lane), their number checked against its count.
    fn list_entries<'n>(&mut self, node: &'n Node) -> Result<&'n [Expr]> {
        let List::Entries { count, entries } = list_view(node)? else {
            return Err(crate::eval::malformed(node, "a list of entries"));
        };
        let n = self.float(count)?;
        let given = entries.len();
        if n.trunc() != given as f64 {
            return Err(Diagnostic::error(
                format!("`{}` announces {n} entries but lists {given}", node.word),
                count.span,
            ));
        }
        Ok(entries)
    }
}

/// A mesh2 list's body.
fn list_view(node: &Node) -> Result<List<'_>> {
    match node.view() {
        View::VertexVectors(list)
        | View::NormalVectors(list)
        | View::UvVectors(list)
        | View::FaceIndices(list)
        | View::NormalIndices(list)
        | View::UvIndices(list) => Ok(list),
        _ => Err(crate::eval::malformed(node, "a mesh2 list")),
    }
}

/// The announced count of a fast-path list must match its entries (as in [`Evaluator::list_entries`]).
fn check_bulk_count(node: &Node, list: &crate::syntax::bulk::BulkList) -> Result<()> {
    let given = list.values.len();
    if list.count.trunc() != given as f64 {
        let (start, end) = list.count_range;
        return Err(Diagnostic::error(
            format!(
                "`{}` announces {} entries but lists {given}",
                node.word, list.count
            ),
            Span::new(node.span.file, start as usize, end as usize),
        ));
    }
    Ok(())
}

enum SmoothNormals {
    /// The three normals equal: the triangle is flat.
    Flat,
    /// A stand-alone smooth triangle with a zero normal, or with normals on both sides of its
    /// face: POV-Ray drops it.
    Degenerate,
    /// Unit normals.
    Smooth([DVec3; 3]),
}

/// A mesh's vertex normal as POV-Ray stores it: a zero one (every component under 1e-10)
/// becomes <1, 0, 0>, and it is made unit.
fn mesh_normal(n: DVec3) -> DVec3 {
    if n.abs().max_element() < 1e-10 {
        DVec3::X
    } else {
        n.normalize()
    }
}

/// POV-Ray's smooth-triangle rules. A mesh's member (`in_mesh`; a `mesh2` face too) is flat
/// when its unit normals are equal to within 1e-10 (squared distance), smooth otherwise, even
/// when its normals lie on both sides of the face (POV-Ray interpolates them as they are). A
/// stand-alone `smooth_triangle` keeps equal normals smooth but is dropped when a normal is
/// zero or the normals are not all on one side of the geometric normal `ng`.
fn smooth_normals(ng: DVec3, n: &[DVec3; 3], in_mesh: bool) -> SmoothNormals {
    if in_mesh {
        let unit = n.map(mesh_normal);
        let apart = |a: DVec3, b: DVec3| (a - b).length_squared() > 1e-10;
        return if apart(unit[0], unit[1]) || apart(unit[0], unit[2]) {
            SmoothNormals::Smooth(unit)
        } else {
            SmoothNormals::Flat
        };
    }
    if n.iter().any(|v| v.length_squared() == 0.0) {
        return SmoothNormals::Degenerate;
    }
    let unit = n.map(|v| v.normalize());
    let sides = unit.map(|v| v.dot(ng));
    if sides.iter().all(|&s| s > 0.0) || sides.iter().all(|&s| s < 0.0) {
        SmoothNormals::Smooth(unit)
    } else {
        SmoothNormals::Degenerate
    }
}

/// A mesh from `mesh2`-style lists, with POV-Ray's rules: zero-area triangles are dropped
/// (returned: the mesh and how many were dropped; their numbers are kept for a mesh camera),
/// a face whose three normals are equal is flat.
/// Per triangle, three indices (of vertices, or of textures).
type Faces = Vec<[u32; 3]>;

/// The index of texture `t` among a mesh's `textures`, added unless one of the last few is
/// equal (exporters give each triangle a copy of the same texture).
fn mesh_texture(textures: &mut Vec<ir::Texture>, t: ir::Texture) -> u32 {
    let recent = textures.len().saturating_sub(8);
    match textures[recent..].iter().position(|u| *u == t) {
        Some(i) => (recent + i) as u32,
        None => {
            textures.push(t);
            textures.len() as u32 - 1
        }
    }
}

pub(in crate::eval) fn assemble_mesh(
    vertices: &[DVec3],
    normals: &[DVec3],
    faces: &[[u32; 3]],
    normal_faces: &[[u32; 3]],
    uv_faces: &[[u32; 3]],
    face_textures: &[[u32; 3]],
) -> (Mesh, usize) {
    let mut mesh = Mesh {
        vertices: vertices.iter().map(|v| v.as_vec3()).collect(),
        normals: Vec::with_capacity(normals.len()),
        triangles: Vec::with_capacity(faces.len()),
        normal_indices: Vec::new(),
        inside_vector: None,
        uvs: Vec::new(),
        uv_indices: Vec::new(),
        world_uv: false,
        textures: Vec::new(),
        face_textures: Vec::new(),
        dropped_faces: Vec::new(),
    };
    let unit_normals: Vec<DVec3> = normals.iter().map(|&n| mesh_normal(n)).collect();
    let mut degenerate = 0usize;
    for (k, face) in faces.iter().enumerate() {
        let p = face.map(|i| vertices[i as usize]);
        let ng = (p[1] - p[0]).cross(p[2] - p[0]);
        if ng.length_squared() == 0.0 {
            degenerate += 1;
            mesh.dropped_faces.push(k as u32);
            continue;
        }
        let mut normal_index = FLAT;
        if let Some(nf) = normal_faces.get(k) {
            let n = nf.map(|i| unit_normals[i as usize]);
            if let SmoothNormals::Smooth(_) = smooth_normals(ng, &n, true) {
                normal_index = *nf;
            }
        }
        mesh.triangles.push(*face);
        if let Some(uv) = uv_faces.get(k) {
            mesh.uv_indices.push(*uv);
        }
        if let Some(t) = face_textures.get(k) {
            mesh.face_textures.push(*t);
        }
        if normal_index != FLAT || !mesh.normal_indices.is_empty() {
            mesh.normal_indices.resize(mesh.triangles.len() - 1, FLAT);
            mesh.normal_indices.push(normal_index);
        }
    }
    if !mesh.normal_indices.is_empty() {
        mesh.normals = unit_normals.iter().map(|v| v.as_vec3()).collect();
    }
    (mesh, degenerate)
}

/// An interior texture given to an object: a second one is layered on the first, as POV-Ray
/// links them.
fn set_interior_texture(object: &mut ObjectValue, texture: Texture) {
    object.interior_texture = Some(match object.interior_texture.take() {
        Some(below) => crate::eval::build::material::layer(texture, below),
        None => texture,
    });
}
