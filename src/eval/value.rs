//! Values that expressions and declarations produce, and POV-Ray's promotion rules.

use crate::ir::{self, Colour, Rgb};
use glam::DVec3;

/// A vector of 2 to 5 components (`<a, b>` … `<a, b, c, d, e>`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vector {
    /// Components; those past `len` are zero.
    pub c: [f64; 5],
    /// Number of components.
    pub len: usize,
}

impl Vector {
    pub fn new(components: &[f64]) -> Vector {
        let mut c = [0.0; 5];
        c[..components.len()].copy_from_slice(components);
        Vector {
            c,
            len: components.len(),
        }
    }

    pub fn vec3(&self) -> DVec3 {
        DVec3::new(self.c[0], self.c[1], self.c[2])
    }

    pub fn from_vec3(v: DVec3) -> Vector {
        Vector::new(&[v.x, v.y, v.z])
    }
}

/// What an expression or a declaration evaluates to.
#[derive(Clone, Debug)]
pub enum Value {
    Float(f64),
    Vector(Vector),
    /// A colour: red, green, blue, filter, transmit.
    Colour([f64; 5]),
    Pigment(Box<ir::Pigment>),
    Media(Box<ir::Media>),
    /// A declared normal.
    Normal(Box<ir::Normal>),
    /// A declared sky_sphere.
    SkySphere(ir::SkySphere),
    Finish(Box<ir::Finish>),
    Texture(Box<ir::Texture>),
    Object(Box<super::ObjectValue>),
    Transform(Box<ir::Transform>),
    Camera(Box<super::build::camera::CameraItems>),
    Interior(Box<ir::Interior>),
    Fog(Box<super::build::scene::FogItems>),
    Rainbow(Box<super::build::scene::RainbowItems>),
    /// `material {…}`: a texture, an interior texture and an interior, each only if given.
    Material(Box<MaterialValue>),
    ColourMap(ir::ColourMap),
    /// A declared pigment_map.
    PigmentMap(Vec<(f64, ir::Pigment)>),
    /// A declared texture_map.
    TextureMap(Vec<(f64, ir::Texture)>),
    /// A declared normal_map.
    NormalMap(Vec<(f64, ir::Normal)>),
    /// A declared slope_map: value, (height, slope).
    SlopeMap(Vec<(f64, [f64; 2])>),
    Str(String),
    /// `array[…]`: its elements row-major, `None` where none was assigned yet.
    Array(Box<Array>),
    /// `function { … }`, compiled.
    Function(std::sync::Arc<crate::func::Function>),
    /// `spline { … }`.
    Spline(std::sync::Arc<crate::func::spline::Spline>),
    /// A file opened by `#fopen` (an index into the evaluator's files).
    File(usize),
    /// A declaration trace could not evaluate: the reason, reported when the name is used.
    Unsupported(Box<crate::diag::Diagnostic>),
}

/// A POV-Ray array: its size along each dimension and its elements in row-major order.
#[derive(Clone, Debug)]
pub struct Array {
    pub dims: Vec<usize>,
    pub items: Vec<Option<Value>>,
}

impl Value {
    /// False for a number, vector or colour with an infinite or NaN component.
    pub fn is_finite(&self) -> bool {
        match self {
            Value::Float(f) => f.is_finite(),
            Value::Vector(v) => v.c.iter().all(|c| c.is_finite()),
            Value::Colour(c) => c.iter().all(|c| c.is_finite()),
            _ => true,
        }
    }

    /// The phrase used in "expected …, found …" messages.
    pub fn kind_name(&self) -> &'static str {
        match self {
            Value::Float(_) => "a float",
            Value::Vector(_) => "a vector",
            Value::Colour(_) => "a colour",
            Value::Pigment(_) => "a pigment",
            Value::Media(_) => "a media",
            Value::Normal(_) => "a normal",
            Value::SkySphere(_) => "a sky_sphere",
            Value::Finish(_) => "a finish",
            Value::Texture(_) => "a texture",
            Value::Object(_) => "an object",
            Value::Transform(_) => "a transform",
            Value::Camera(_) => "a camera",
            Value::Interior(_) => "an interior",
            Value::Fog(_) => "a fog",
            Value::Rainbow(_) => "a rainbow",
            Value::Material(..) => "a material",
            Value::ColourMap(_) => "a color_map",
            Value::PigmentMap(_) => "a pigment_map",
            Value::TextureMap(_) => "a texture_map",
            Value::NormalMap(_) => "a normal_map",
            Value::SlopeMap(_) => "a slope_map",
            Value::Str(_) => "a string",
            Value::Array(_) => "an array",
            Value::Function(_) => "a function",
            Value::File(_) => "a file",
            Value::Spline(_) => "a spline",
            Value::Unsupported(_) => "an unsupported value",
        }
    }

    /// Components of a float, vector or colour (a float is one component).
    pub fn components(&self) -> Option<([f64; 5], usize)> {
        match self {
            Value::Float(f) => Some(([*f, 0.0, 0.0, 0.0, 0.0], 1)),
            Value::Vector(v) => Some((v.c, v.len)),
            Value::Colour(c) => Some((*c, 5)),
            _ => None,
        }
    }
}

/// A five-channel colour from a value in a pigment-colour context: a float fills all five
/// channels, a shorter vector is padded with zeros.
pub fn colour5(value: &Value) -> Option<[f64; 5]> {
    match value {
        Value::Float(f) => Some([*f; 5]),
        Value::Vector(v) => Some(v.c),
        Value::Colour(c) => Some(*c),
        _ => None,
    }
}

/// An RGB colour from a value in an RGB-only context (light colour, ambient …): a float fills
/// the three channels.
pub fn rgb(value: &Value) -> Option<Rgb> {
    match value {
        Value::Float(f) => Some(Rgb::splat(*f)),
        Value::Vector(v) => Some(v.vec3()),
        Value::Colour(c) => Some(Rgb::new(c[0], c[1], c[2])),
        _ => None,
    }
}

/// The IR colour of five channels.
pub fn to_colour(c: [f64; 5]) -> Colour {
    Colour {
        rgb: Rgb::new(c[0], c[1], c[2]),
        filter: c[3],
        transmit: c[4],
    }
}

/// sRGB decode of one channel (for `srgb` colours).
pub fn srgb_decode(v: f64) -> f64 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// What a `material {…}` sets: each only if given.
#[derive(Clone, Debug, Default)]
pub struct MaterialValue {
    /// `texture {…}`.
    pub texture: Option<ir::Texture>,
    /// `interior_texture {…}`.
    pub interior_texture: Option<ir::Texture>,
    /// `interior {…}`.
    pub interior: Option<ir::Interior>,
}

#[cfg(test)]
mod tests {
    /// A value is small: an array of a million numbers (a height field a scene computes)
    /// holds a million of them, and every word the reader binds keeps one alive. The large
    /// materials are boxed.
    #[test]
    fn a_value_is_no_larger_than_a_vector() {
        assert!(std::mem::size_of::<super::Value>() <= std::mem::size_of::<super::Vector>() + 8);
    }
}
