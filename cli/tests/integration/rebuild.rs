//! Building a scene again from the last build (`trace watch` at every save): what an edit
//! leaves unchanged is kept, and the picture is the one a fresh build gives.

use std::path::Path;

/// A scene of twenty small spheres in a row (enough for a top-level tree), a sphere, a
/// torus and an isosurface of a user function, with one piece of its text replaced.
fn scene(edit: (&str, &str)) -> trace::ir::Scene {
    let text = "
        #declare F = function(x, y, z) { x*x + y*y + z*z - 0.25 }
        camera { location <0, 2, -8> look_at <0, 0, 0> }
        light_source { <-5, 8, -6>, rgb 1 }
        plane { y, -1 pigment { checker rgb 1, rgb 0.3 } }
        #for (i, 0, 19)
            sphere { <i/4 - 2.5, 0, 0>, 0.12 pigment { rgb <1, i/20, 0> } }
        #end
        sphere { <0, 1, 0>, 0.5 pigment { rgb <0, 0.5, 1> } finish { phong 0.5 } }
        torus { 0.6, 0.15 rotate 60*x translate <2, 1, 0> pigment { rgb 0.8 } }
        isosurface { function { F(x, y, z) } contained_by { box { -1, 1 } }
            translate <-2, 1, 0> pigment { bozo } }
        #declare Moved = 0;
    ";
    assert!(text.contains(edit.0), "the edit applies: {edit:?}");
    let text = text.replacen(edit.0, edit.1, 1);
    let options = trace::LoadOptions {
        width: 64,
        height: 48,
        ..Default::default()
    };
    trace::load_str(Path::new("rebuild.rt"), text, &options)
        .unwrap_or_else(|e| panic!("{e}"))
        .scene
}

fn options() -> trace::RenderOptions {
    trace::RenderOptions {
        width: 64,
        height: 48,
        threads: Some(2),
        ..Default::default()
    }
}

#[test]
fn a_rebuild_keeps_what_the_edit_left_and_renders_as_a_fresh_build() {
    let base = scene(("", ""));
    let objects = base.objects.len();
    let cache = trace::BuildCache::default();
    // (edit, shapes kept, tree kept)
    let cases = [
        // A light moved: no geometry built.
        (("<-5, 8, -6>", "<3, 8, -6>"), objects, true),
        // A material edited: none either.
        (("phong 0.5", "phong 0.9 reflection 0.3"), objects, true),
        (("pigment { bozo }", "pigment { granite }"), objects, true),
        // The function changed: the isosurface alone is built again (its bounds unchanged).
        (("- 0.25 }", "- 0.3 }"), objects - 1, true),
        // One sphere moved: it alone is built again, and the tree too.
        (("<0, 1, 0>, 0.5", "<0, 1.2, 0>, 0.5"), objects - 1, false),
        // Another noise generator: every shape built again (a shape's build may read it),
        // the bounds and so the tree unchanged.
        (
            (
                "#declare Moved = 0;",
                "global_settings { noise_generator 1 }",
            ),
            0,
            true,
        ),
        // A sphere more at the start: the others keep their shapes, found as far from the end
        // as before.
        (
            (
                "plane {",
                "sphere { <0, 3, 0>, 0.2 pigment { rgb 1 } } plane {",
            ),
            objects,
            false,
        ),
        // One removed in the middle: the others keep theirs.
        (
            (
                "sphere { <0, 1, 0>, 0.5 pigment { rgb <0, 0.5, 1> } finish { phong 0.5 } }",
                "",
            ),
            objects - 1,
            false,
        ),
        // A sphere more (the last one): those before are kept.
        (
            (
                "#declare Moved = 0;",
                "sphere { <1, -0.5, -1>, 0.3 pigment { rgb 1 } }",
            ),
            objects,
            false,
        ),
    ];
    for (edit, shapes, tree) in cases {
        let prepared = trace::prepare(&base, Some(2), &cache).expect("threads");
        let edited = scene(edit);
        let (again, reuse) = prepared.rebuild(&edited, &base, &cache);
        assert_eq!(
            (reuse.shapes, reuse.tree),
            (shapes, tree),
            "{edit:?}: {reuse:?}"
        );
        assert_eq!(reuse.objects, edited.objects.len());
        let fresh = trace::render(&edited, &options()).expect("a render");
        let rebuilt = again.render(&options());
        assert!(
            rebuilt.film.pixels == fresh.film.pixels,
            "{edit:?}: the rebuilt scene's picture differs from a fresh build's"
        );
        // The edit shows (the test would not see a rebuild that ignored it).
        let before = trace::render(&base, &options()).expect("a render");
        assert!(before.film.pixels != fresh.film.pixels, "{edit:?} shows");
    }
}

/// A mesh2 whose lists the fast lane reads is made once while its lists' text is unchanged:
/// a second load with the same list cache gets the very same mesh (and its warnings again);
/// any change to the lists or the inside vector makes it anew, equal to a fresh load's.
#[test]
fn a_mesh2_of_unchanged_lists_is_made_once() {
    let text = |vertex: &str, inside: &str| {
        let n = 40;
        let mut vertices: Vec<String> = (0..=n)
            .flat_map(|j| (0..=n).map(move |i| format!("<{i}, {}, {j}>", (i * j) % 3)))
            .collect();
        vertices[5] = vertex.to_string();
        let mut faces: Vec<String> = Vec::new();
        for j in 0..n {
            for i in 0..n {
                let a = j * (n + 1) + i;
                faces.push(format!("<{a}, {}, {}>", a + 1, a + n + 1));
                faces.push(format!("<{}, {}, {}>", a + 1, a + n + 2, a + n + 1));
            }
        }
        // One zero-area triangle: a warning at every load.
        faces.push("<0, 0, 1>".into());
        format!(
            "camera {{ location <20, 30, -30> look_at <20, 0, 20> }}\n\
             mesh2 {{ vertex_vectors {{ {}, {} }} face_indices {{ {}, {} }} {inside} pigment {{ rgb 1 }} }}\n",
            vertices.len(),
            vertices.join(", "),
            faces.len(),
            faces.join(", "),
        )
    };
    let lists = trace::ListCache::default();
    let options = trace::LoadOptions {
        lists: lists.clone(),
        ..Default::default()
    };
    let load = |text: String, options: &trace::LoadOptions| {
        let loaded =
            trace::load_str(Path::new("mesh.rt"), text, options).unwrap_or_else(|e| panic!("{e}"));
        let trace::ir::Shape::Mesh(mesh) = &loaded.scene.objects[0].shape else {
            panic!("a mesh");
        };
        (mesh.clone(), loaded.warnings)
    };
    let (first, warned) = load(text("<5, 0, 0>", ""), &options);
    assert_eq!(warned.len(), 1, "{warned:?}");
    let (again, warned_again) = load(text("<5, 0, 0>", ""), &options);
    assert!(std::sync::Arc::ptr_eq(&first, &again), "the same mesh");
    assert_eq!(warned_again, warned, "its warning again");
    for (vertex, inside) in [("<5, 0.5, 0>", ""), ("<5, 0, 0>", "inside_vector y")] {
        let (changed, _) = load(text(vertex, inside), &options);
        assert!(
            !std::sync::Arc::ptr_eq(&first, &changed),
            "{vertex} {inside}"
        );
        let (fresh, _) = load(text(vertex, inside), &trace::LoadOptions::default());
        assert!(
            *changed == *fresh,
            "{vertex} {inside}: as a fresh load makes it"
        );
        assert!(*changed != *first);
    }
}
