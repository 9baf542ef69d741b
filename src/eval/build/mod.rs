//! The IR builder: objects, shapes, materials, images, transforms.
//!
//! Turns the blocks of a statement into the IR (`ir::Object`, `ir::Texture`, …), asking the
//! language (`super::lang`) for each value inside them, and applies POV-Ray's defaults and
//! fixed orders (texture attachment, a light's group, the camera's items).

pub(super) mod camera;
pub(super) mod heightfield;
pub(super) mod images;
pub(super) mod light;
pub(super) mod material;
pub(super) mod object;
pub(super) mod scene;
pub(super) mod shapes;
pub(super) mod transform;

use crate::eval::ObjectQueryMaker;
use crate::eval::build::camera::CameraItems;
use crate::ir::{self, Rgb, Texture};
use std::collections::HashMap;
use std::sync::Arc;

/// What the IR builder keeps while a scene is read: the scene gathered so far (camera,
/// lights, objects, sky, fog, settings), the defaults statements set, and what is shared
/// between objects (finishes, interiors, mesh files, fonts, objects asked by `trace()`).
pub(in crate::eval) struct Builder {
    pub(in crate::eval) sky_sphere: Option<ir::SkySphere>,
    pub(in crate::eval) fogs: Vec<ir::Fog>,
    /// Top-level `media { … }`: the atmosphere.
    pub(in crate::eval) atmosphere: Vec<ir::Media>,
    /// `rainbow { … }` statements that can be seen.
    pub(in crate::eval) rainbows: Vec<ir::Rainbow>,
    pub(in crate::eval) settings: ir::Settings,
    /// Whether `radiosity { … }` gave `minimum_reuse` and `maximum_reuse` (POV-Ray's rule
    /// for the two, applied once the scene is read, moves only one it was not given), and
    /// where the block stood.
    pub(in crate::eval) reuse_given: (bool, bool, Option<crate::diag::Span>),
    /// `#default { radiosity { importance F } }`, the last given.
    pub(in crate::eval) default_importance: Option<f64>,
    pub(in crate::eval) camera: Option<CameraItems>,
    pub(in crate::eval) lights: Vec<ir::Light>,
    pub(in crate::eval) objects: Vec<ir::Object>,
    /// The next unused [`ir::Object::medium`].
    pub(in crate::eval) next_medium: u32,
    /// The next `light_group`'s number.
    pub(in crate::eval) next_light_group: u32,
    /// The amount of a normal that gives none (`#default { normal { bump_size B } }`).
    pub(in crate::eval) default_bump_size: f64,
    pub(in crate::eval) background: Rgb,
    pub(in crate::eval) background_alpha: f64,
    pub(in crate::eval) default_texture: Texture,
    /// The interior of objects without one, shared by all of them.
    pub(in crate::eval) default_interior: std::sync::Arc<ir::Interior>,
    /// Finishes and interiors made so far, by the bits of their values: an equal one made
    /// again is shared (a million spheres each with `finish { phong 0.5 }` hold one finish).
    pub(in crate::eval) finishes: HashMap<u64, std::sync::Arc<ir::Finish>>,
    pub(in crate::eval) interiors: HashMap<u64, std::sync::Arc<ir::Interior>>,
    /// Image files decoded so far, by path and format: a file used twice is decoded once.
    pub(in crate::eval) pictures:
        HashMap<(std::path::PathBuf, super::build::images::FileType), Arc<images::Picture>>,
    /// Texels made so far, by file and the settings that make them: maps of the same file
    /// with the same settings share one copy.
    pub(in crate::eval) texels: HashMap<String, Arc<crate::pattern::image::Texels>>,
    /// Mesh files read so far: a file used twice is read and stored once.
    pub(in crate::eval) mesh_files: HashMap<std::path::PathBuf, std::sync::Arc<ir::Mesh>>,
    /// How `text` reads its strings (`global_settings { charset … }`).
    pub(in crate::eval) charset: crate::font::Charset,
    /// Font files read, by path (`text`).
    pub(in crate::eval) fonts: HashMap<std::path::PathBuf, std::sync::Arc<Vec<u8>>>,
    /// Makes objects that answer trace() and its kin.
    pub(in crate::eval) object_query: ObjectQueryMaker,
    /// The id of the last object made (see `ObjectValue::id`).
    pub(in crate::eval) next_object_id: u64,
    /// Objects asked by trace() and its kin so far, by id (a scatter loop asks one object
    /// thousands of times).
    pub(in crate::eval) queries: HashMap<u64, Arc<dyn ir::ObjectQuery>>,
}
