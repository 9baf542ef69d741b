use super::{MeshData, obj, ply, write_mesh2};
use glam::DVec3;

const QUAD_OBJ: &str = "\
# a unit quad with normals
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vn 0 0 -1
vt 0 0
f 1//1 2//1 3//1 -1//1
";

#[test]
fn obj_polygons_become_fans_and_indices_resolve() {
    let m = obj::parse(QUAD_OBJ.as_bytes()).unwrap();
    assert_eq!(m.vertices.len(), 4);
    assert_eq!(m.faces, vec![[0, 1, 2], [0, 2, 3]]);
    assert_eq!(m.normals, vec![DVec3::new(0.0, 0.0, -1.0)]);
    assert_eq!(m.normal_faces, vec![[0, 0, 0], [0, 0, 0]]);
}

#[test]
fn obj_faces_without_normals_make_the_mesh_flat() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1/1 2/2 3/3\n";
    let m = obj::parse(text.as_bytes()).unwrap();
    assert_eq!(m.faces.len(), 2);
    assert!(m.normals.is_empty() && m.normal_faces.is_empty());
}

#[test]
fn obj_errors_name_the_line() {
    let cases = [
        ("v 0 0 0\nv 1 x 0\n", 2, "`x` is not a number"),
        ("v 0 0 0\nv 1 0\n", 2, "`v` needs 3 numbers, found 2"),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n",
            5,
            "vertex index 4 is out of range (the file has 3 vertices so far)",
        ),
        (
            "v 0 0 0\nv 1 0 0\nf 1 2\n",
            3,
            "a face needs 3 corners, found 2",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n",
            4,
            "vertex index 0 is out of range",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//2 2//2 3//2\n",
            4,
            "normal index 2 is out of range",
        ),
    ];
    for (text, line, message) in cases {
        let (at, m) = obj::parse(text.as_bytes()).unwrap_err();
        assert_eq!(at, Some(line), "{text:?}: {m}");
        assert!(m.contains(message), "{text:?}: {m}");
    }
}

fn ply_header(format: &str, faces: usize) -> String {
    format!(
        "ply\nformat {format} 1.0\ncomment made by hand\nelement vertex 4\nproperty float x\n\
         property float y\nproperty float z\nelement face {faces}\n\
         property list uchar int vertex_indices\nend_header\n"
    )
}

fn expected_quad() -> MeshData {
    MeshData {
        vertices: vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.5),
        ],
        normals: vec![],
        faces: vec![[0, 1, 2], [0, 2, 3]],
        normal_faces: vec![],
    }
}

#[test]
fn ply_ascii_and_both_binary_orders_read_alike() {
    let ascii = ply_header("ascii", 1) + "0 0 0\n1 0 0\n1 1 0\n0 1 0.5\n4 0 1 2 3\n";
    assert_eq!(ply::parse(ascii.as_bytes()).unwrap(), expected_quad());
    for (format, big) in [("binary_little_endian", false), ("binary_big_endian", true)] {
        let mut bytes = ply_header(format, 1).into_bytes();
        for v in expected_quad().vertices {
            for c in [v.x as f32, v.y as f32, v.z as f32] {
                bytes.extend(if big {
                    c.to_be_bytes()
                } else {
                    c.to_le_bytes()
                });
            }
        }
        bytes.push(4);
        for i in 0..4i32 {
            bytes.extend(if big {
                i.to_be_bytes()
            } else {
                i.to_le_bytes()
            });
        }
        assert_eq!(ply::parse(&bytes).unwrap(), expected_quad(), "{format}");
    }
}

#[test]
fn ply_errors_name_the_line_or_element() {
    let quad = "0 0 0\n1 0 0\n1 1 0\n0 1 0.5\n";
    let cases = [
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n".to_string(),
            None,
            "no `end_header`",
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n".to_string(),
            Some(4),
            "unknown property type `quad`",
        ),
        (
            ply_header("ascii", 1) + quad + "3 0 1 7\n",
            Some(15),
            "vertex index 7 out of range",
        ),
        (
            ply_header("ascii", 1) + "0 0 0\n1 zero 0\n",
            Some(12),
            "`zero` is not a number",
        ),
        (
            ply_header("ascii", 1) + "0 0 0\n1 0 0 9\n",
            Some(12),
            "unexpected `9`",
        ),
        (
            ply_header("ascii", 2) + quad + "3 0 1 2\n",
            Some(15),
            "face 1: the file ends early",
        ),
        (
            ply_header("binary_little_endian", 1) + "\0\0",
            None,
            "vertex 0: the file ends early",
        ),
        ("plyx\n".to_string(), Some(1), "not a PLY file"),
        (
            ply_header("ascii", 1) + "0 0 0\n1 nan 0\n",
            Some(12),
            "vertex 1: a coordinate or normal is not a finite number",
        ),
    ];
    for (text, line, message) in cases {
        let (at, m) = ply::parse(text.as_bytes()).unwrap_err();
        assert!(m.contains(message), "{text:?}: {m}");
        assert_eq!(at, line, "{text:?}: {m}");
    }
    let mut nan = ply_header("binary_little_endian", 1).into_bytes();
    for c in [f32::NAN, 0.0, 0.0] {
        nan.extend(c.to_le_bytes());
    }
    let (_, m) = ply::parse(&nan).unwrap_err();
    assert!(
        m.contains("vertex 0: a coordinate or normal is not a finite number"),
        "{m}"
    );
}

#[test]
fn mesh2_output_lists_every_section() {
    let mut m = expected_quad();
    m.normals = vec![DVec3::Z];
    m.normal_faces = vec![[0, 0, 0], [0, 0, 0]];
    let mut out = Vec::new();
    write_mesh2(&m, "Quad", &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("#declare Quad = mesh2 {"));
    assert!(text.contains(
        "vertex_vectors { 4,\n    <0,0,0>,\n    <1,0,0>,\n    <1,1,0>,\n    <0,1,0.5>\n  }"
    ));
    assert!(text.contains("normal_vectors { 1,\n    <0,0,1>\n  }"));
    assert!(text.contains("face_indices { 2,\n    <0,1,2>,\n    <0,2,3>\n  }"));
    assert!(text.contains("normal_indices { 2,"));
}
