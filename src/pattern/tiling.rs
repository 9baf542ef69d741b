//! POV-Ray 3.7's `tiling` pattern.
//!
//! `tiling N` (N = 1 ..= 27) covers the x-z plane with one of 27 tilings: 24 periodic ones
//! made of squares, rectangles, triangles, lozenges, hexagons, octagons and dodecagons, and
//! three aperiodic Penrose tilings centred on the origin. The y coordinate plays no part: the
//! pattern is a prism along y.
//!
//! The value at a point says which kind of tile the point is in and where in the tile it is.
//! Each kind of tile (a shape, sometimes a shape in one orientation) owns a band of [0, 1]:
//! the whole range when there is one kind, halves, thirds, fifths or sixths otherwise. Inside
//! its band the value grows from the tile's middle to its border (tiling 3's upward triangles,
//! for instance, go from 0 in the middle to ½ on the edges, the downward ones from ½ to 1).
//! Some tilings keep a hair's breadth (1e-12 to 1e-6) inside a band's end, so that a colour
//! map can tell the tiles apart.
//!
//! The formulas are POV-Ray 3.7.0's, with its constants and its order of operations, so that
//! points on the edges between tiles, and at the ends of the bands, get the same value.

use std::f64::consts::{FRAC_1_SQRT_2, SQRT_2};

/// √3.
const SQRT3: f64 = 1.7320508075688772;
/// √3 / 2: the height of a triangle of side 1.
const HALF_SQRT3: f64 = 0.8660254037844386;

const SIN18: f64 = 0.30901699437494745;
const SIN36: f64 = 0.5877852522924731;
const SIN54: f64 = 0.8090169943749475;
const SIN72: f64 = 0.9510565162951535;
const SIN108: f64 = SIN72;
const SIN144: f64 = SIN36;
const SIN162: f64 = SIN18;
const COS18: f64 = SIN72;
const COS36: f64 = SIN54;
const COS72: f64 = SIN18;
const COS108: f64 = -COS72;
const COS144: f64 = -COS36;
const COS162: f64 = -COS18;
const TAN18: f64 = 0.32491969623290634;
const TAN36: f64 = 0.7265425280053609;
const TAN54: f64 = 1.3763819204711736;
const TAN72: f64 = 3.0776835371752536;
const TAN108: f64 = -TAN72;
const TAN126: f64 = -TAN54;
const TAN144: f64 = -TAN36;
const TAN162: f64 = -TAN18;

/// The golden ratio φ.
const PHI: f64 = 1.618033988749895;
/// 1/φ.
const INV_PHI: f64 = 0.6180339887498949;
/// 1/φ².
const INV_PHI_SQUARED: f64 = 0.38196601125010515;
/// ln φ² (rounded from the exact value, as a compiler folds it).
const LN_PHI_SQUARED: f64 = 0.9624236501192069;
/// ln φ⁴ (of the double φ² · φ²).
const LN_PHI_FOURTH: f64 = 1.9248473002384139;

/// The margin that keeps some tiles inside their band.
const BAND_MARGIN: f64 = 1e-6;

/// POV-Ray's `tiling n` pattern (1 to 27) at point `p` (x, y, z): the value in [0, 1] before
/// any colour map, as POV-Ray 3.7 computes it. Numbers outside 1..=27 behave as POV-Ray does.
///
/// This is the pattern's own value, the one that then goes through the pattern's wave
/// (`frequency`, `phase`, wave shape). It stays in [0, 1] but for POV-Ray's own exceptions:
/// a few tilings reach a hair above 1 (at most 1.0000004) on tile edges, and on some lines of
/// a tiling's period grid (and at tiny negative coordinates, which wrap onto the end of the
/// period) the cell arithmetic runs past its table of tiles and gives values up to 5
/// (`tiling 12` at x = 6 gives 7/3, which the default wave, fmod 1.00001, turns into 0.33331).
///
/// POV-Ray keeps only the low byte of the number (`tiling 261` is `tiling 5`, `tiling -251`
/// too), and refuses a scene whose byte is not 1 ..= 27 ("Tiling number must be between 1 and
/// 27"); those numbers give tiling 1 here, as POV-Ray's evaluator would.
pub fn tiling(n: i32, p: [f64; 3]) -> f64 {
    let [x, _, z] = p;
    match n & 0xff {
        2 => hexagons(x, z),
        3 => triangles(x, z),
        4 => lozenges(x, z),
        5 => rhombuses(x, z),
        6 => rectangles(x, z),
        7 => octagons_and_squares(x, z),
        8 => squares_and_triangles(x, z),
        9 => hexagons_and_triangles(x, z),
        10 => offset_squares(x, z),
        11 => square_and_rectangles(x, z),
        12 => square_and_mirrored_rectangles(x, z),
        13 => inner_squares(x, z),
        14 => inner_squares_5(x, z),
        15 => small_and_big_squares(x, z),
        16 => hexagons_squares_triangles(x, z),
        17 => hexagons_squares_triangles_6(x, z),
        18 => rectangle_pairs(x, z),
        19 => snub_hexagonal(x, z, Hand::Right),
        20 => snub_hexagonal(x, z, Hand::Left),
        21 => snub_square(x, z),
        22 => dodecagons_and_triangles(x, z),
        23 => dodecagons_hexagons_squares(x, z),
        24 => dodecagons_hexagons_squares_5(x, z),
        25 => penrose_pentagons(x, z),
        26 => penrose(x, z, Penrose::KitesAndDarts),
        27 => penrose(x, z, Penrose::Rhombs),
        _ => squares(x, z),
    }
}

// ---------------------------------------------------------------------------------------------
// Shared pieces
// ---------------------------------------------------------------------------------------------

/// `v` brought into [0, `period`) (or onto `period` itself, when rounding lands there).
fn wrap(v: f64, period: f64) -> f64 {
    v - period * (v / period).floor()
}

/// C's conversion of a double to `int` on x86-64: truncation, and `INT_MIN` for anything out
/// of range.
fn c_int(v: f64) -> i32 {
    if (-2147483648.0..2147483648.0).contains(&v) {
        v as i32
    } else {
        i32::MIN
    }
}

/// Distance-like coordinate across a unit cell: 0 in the middle of [0, 1], 1 at its ends.
fn tent(v: f64) -> f64 {
    2.0 * (v - 0.5).abs()
}

/// Distance-like coordinate across a bar centred on 0 and reaching ±1: 0 over its middle half,
/// rising to 1 at its ends.
fn bar(v: f64) -> f64 {
    2.0 * (v.abs().max(0.5) - 0.5)
}

/// Folds a point of the triangle strip (x in [0, ½], z in [0, √3/2]) into the upward triangle
/// whose base is z = 0. Returns the folded point and whether it came from the downward
/// triangle. A point on the axis x = 0 is always moved; it counts as flipped only if
/// `axis_flips`.
fn fold_triangle(x: f64, z: f64, axis_flips: bool) -> (f64, f64, bool) {
    if x == 0.0 {
        (0.5, HALF_SQRT3 - z, axis_flips)
    } else if z / x > SQRT3 {
        (0.5 - x, HALF_SQRT3 - z, true)
    } else {
        (x, z, false)
    }
}

/// Border distance in the upward unit triangle of [`fold_triangle`]: 0 at its centre, 1 on its
/// edges.
fn triangle_distance(x: f64, z: f64) -> f64 {
    let base = 1.0 - (z * 2.0 * SQRT3);
    let side = 1.0 - ((SQRT3 * x - z) * SQRT3);
    base.max(side)
}

/// The strip of unit triangles (period 1 along x, √3 along z): the border distance and
/// whether the point is in a downward triangle (for the second half of the tiling's band).
fn unit_triangles(x: f64, z: f64, axis_flips: bool) -> (f64, bool) {
    let mut x = wrap(x, 1.0);
    let mut z = wrap(z, SQRT3);
    let mut down = false;
    if z > HALF_SQRT3 {
        z = SQRT3 - z;
        down = true;
    }
    if x > 0.5 {
        x = 1.0 - x;
    }
    let (x, z, flipped) = fold_triangle(x, z, axis_flips);
    (triangle_distance(x, z), down != flipped)
}

/// Band value of a hexagon of side 1 among the triangles of tilings 9, 19 and 20, from a point
/// folded into a twelfth of it (`x` in [0, 1], the hexagon's centre at (1, √3/2)): from just
/// above ⅔ in the middle (never below `floor` / 3) to 1 on the edge.
fn hexagon_band(x: f64, z: f64, floor: f64) -> f64 {
    let across = 2.0 + 2.0 * (z * SQRT3);
    let slanted = 2.0 + 2.0 * (SQRT3 * x + z - HALF_SQRT3) * HALF_SQRT3;
    (5.0 - across.min(slanted)).max(floor) / 3.0
}

/// The lozenge strip (period 1 along x): the folding and border distance shared by tilings 4
/// and 5, from a point with z in [0, √3/2].
fn lozenge_distance(x: f64, z: f64) -> f64 {
    let (mut x, mut z) = (x, z);
    if 2.0 * z > HALF_SQRT3 {
        z = HALF_SQRT3 - z;
        x = 1.5 - x;
    }
    if x > 0.75 {
        x -= 1.0;
    }
    if x != 0.0 && z / x > SQRT3 {
        z = HALF_SQRT3 - z;
        x = 0.5 - x;
    }
    let long = 1.0 - (z * 4.0 * SQRT3 / 3.0);
    let short = 1.0 - ((SQRT3 * x - z).abs() * SQRT3 * 2.0 / 3.0);
    long.max(short)
}

/// How a tile of the rectangle tilings is laid: the offset from the point's unit cell to the
/// tile's reference corner, and the tile's kind.
type Cell<K> = (f64, f64, K);

/// Looks up the unit cell holding (x, z) — already wrapped into a `width` × `width` period —
/// in a row-major table, and moves the point to the tile's reference corner. A point that
/// rounds onto the far edge of the period takes the entry its index reaches, or none (no
/// move, kind `default`), as in POV-Ray.
fn cell_lookup<K: Copy>(x: f64, z: f64, width: i32, table: &[Cell<K>], default: K) -> Cell<K> {
    let index = x as i32 + (z as i32) * width;
    match usize::try_from(index).ok().and_then(|i| table.get(i)) {
        Some(&(dx, dz, kind)) => (x - dx, z - dz, kind),
        None => (x, z, default),
    }
}

/// A 2 × 1 rectangle's orientation, or a unit square.
#[derive(Clone, Copy, PartialEq)]
enum Block {
    /// Unit square on [0, 1]².
    Square,
    /// Along z: x in [0, 1], z in [-1, 1].
    AlongZ,
    /// Along x: x in [-1, 1], z in [0, 1].
    AlongX,
}

impl Block {
    /// Border distance (0 inside the middle, 1 on the edge) of a point relative to the
    /// block's reference corner.
    fn distance(self, x: f64, z: f64) -> f64 {
        match self {
            Block::Square => tent(x).max(tent(z)),
            Block::AlongZ => tent(x).max(bar(z)),
            Block::AlongX => bar(x).max(tent(z)),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Squares and rectangles
// ---------------------------------------------------------------------------------------------

/// tiling 1: unit squares. 0 at a square's centre, 1 on its edges.
fn squares(x: f64, z: f64) -> f64 {
    let x = x.abs();
    let z = z.abs();
    tent(x - x.floor()).max(tent(z - z.floor()))
}

/// tiling 10: unit squares, every other row shifted by half a square. 0 at the centre, 1 on
/// the edges.
fn offset_squares(x: f64, z: f64) -> f64 {
    let mut z = wrap(z, 2.0);
    let mut x = x;
    if z > 1.0 {
        x += 0.5;
        z -= 1.0;
    }
    tent(x - x.floor()).max(tent(z))
}

/// tiling 6: 2 × 1 rectangles in a herringbone, in a 4 × 4 period. Rectangles along x
/// have [0, ½], rectangles along z [½, 1].
fn rectangles(x: f64, z: f64) -> f64 {
    use Block::{AlongX as X, AlongZ as Z};
    const TABLE: [Cell<Block>; 16] = [
        (0.0, 1.0, Z),
        (2.0, 0.0, X),
        (2.0, 0.0, X),
        (3.0, 0.0, Z),
        (0.0, 1.0, Z),
        (1.0, 2.0, Z),
        (3.0, 1.0, X),
        (3.0, 1.0, X),
        (0.0, 2.0, X),
        (1.0, 2.0, Z),
        (2.0, 3.0, Z),
        (4.0, 2.0, X),
        (1.0, 3.0, X),
        (1.0, 3.0, X),
        (2.0, 3.0, Z),
        (3.0, 4.0, Z),
    ];
    let (x, z, block) = cell_lookup(wrap(x, 4.0), wrap(z, 4.0), 4, &TABLE, Z);
    let half = if block == Z { 0.5 } else { 0.0 };
    (block.distance(x, z) / 2.0 + half).abs()
}

/// tiling 18: pairs of 2 × 1 rectangles side by side, the pairs alternating in direction
/// (a basket weave), in a 4 × 4 period. Rectangles along x have [0, ½], rectangles along z [½, 1].
fn rectangle_pairs(x: f64, z: f64) -> f64 {
    use Block::{AlongX as X, AlongZ as Z};
    const TABLE: [Cell<Block>; 16] = [
        (0.0, 1.0, Z),
        (1.0, 1.0, Z),
        (3.0, 0.0, X),
        (3.0, 0.0, X),
        (0.0, 1.0, Z),
        (1.0, 1.0, Z),
        (3.0, 1.0, X),
        (3.0, 1.0, X),
        (1.0, 2.0, X),
        (1.0, 2.0, X),
        (2.0, 3.0, Z),
        (3.0, 3.0, Z),
        (1.0, 3.0, X),
        (1.0, 3.0, X),
        (2.0, 3.0, Z),
        (3.0, 3.0, Z),
    ];
    let (x, z, block) = cell_lookup(wrap(x, 4.0), wrap(z, 4.0), 4, &TABLE, Z);
    let band = if block == Z { 1.0 } else { 0.0 };
    ((block.distance(x, z) + band) / 2.0).abs()
}

/// The 3 × 3 pinwheel of tilings 11 and 12: a unit square ([0, ⅓]) with four 2 × 1
/// rectangles around it, along x ([⅓, ⅔]) and along z ([⅔, 1]). `x` and `z` are in [0, 3].
fn pinwheel(x: f64, z: f64) -> f64 {
    use Block::{AlongX as X, AlongZ as Z, Square as S};
    const TABLE: [Cell<Block>; 9] = [
        (0.0, 1.0, Z),
        (2.0, 0.0, X),
        (2.0, 0.0, X),
        (0.0, 1.0, Z),
        (1.0, 1.0, S),
        (2.0, 2.0, Z),
        (1.0, 2.0, X),
        (1.0, 2.0, X),
        (2.0, 2.0, Z),
    ];
    let (x, z, block) = cell_lookup(x, z, 3, &TABLE, Z);
    let band = match block {
        S => 0.0,
        X => 1.0,
        Z => 2.0,
    };
    (block.distance(x, z) + band) / 3.0
}

/// tiling 11: a unit square ringed by four 2 × 1 rectangles turning around it, in a 3 × 3
/// period. Square [0, ⅓], rectangles along x [⅓, ⅔], along z [⅔, 1].
fn square_and_rectangles(x: f64, z: f64) -> f64 {
    pinwheel(wrap(x, 3.0), wrap(z, 3.0))
}

/// tiling 12: the pinwheel of tiling 11 mirrored in x and z every 3 units (a 6 × 6 period),
/// so the rectangles turn both ways. Same bands as tiling 11.
fn square_and_mirrored_rectangles(x: f64, z: f64) -> f64 {
    pinwheel((wrap(x, 6.0) - 3.0).abs(), (wrap(z, 6.0) - 3.0).abs())
}

/// tiling 15: unit squares and 2 × 2 squares, in a 5 × 5 period. Small squares [0, ½], big
/// squares just above ½ to 1.
fn small_and_big_squares(x: f64, z: f64) -> f64 {
    const BIG: f64 = 0.50000001;
    const TABLE: [Cell<f64>; 25] = [
        (0.0, 0.0, 0.0),
        (2.0, 0.0, BIG),
        (2.0, 0.0, BIG),
        (4.0, 1.0, BIG),
        (4.0, 1.0, BIG),
        (1.0, 2.0, BIG),
        (1.0, 2.0, BIG),
        (2.0, 1.0, 0.0),
        (4.0, 1.0, BIG),
        (4.0, 1.0, BIG),
        (1.0, 2.0, BIG),
        (1.0, 2.0, BIG),
        (3.0, 3.0, BIG),
        (3.0, 3.0, BIG),
        (4.0, 2.0, 0.0),
        (0.0, 4.0, BIG),
        (1.0, 3.0, 0.0),
        (3.0, 3.0, BIG),
        (3.0, 3.0, BIG),
        (5.0, 4.0, BIG),
        (0.0, 4.0, BIG),
        (2.0, 5.0, BIG),
        (2.0, 5.0, BIG),
        (3.0, 4.0, 0.0),
        (5.0, 4.0, BIG),
    ];
    let (x, z, base) = cell_lookup(wrap(x, 5.0), wrap(z, 5.0), 5, &TABLE, BIG);
    let distance = if base != 0.0 {
        bar(x).max(bar(z))
    } else {
        tent(x).max(tent(z))
    };
    (distance / 2.0 + base).abs()
}

/// One axis of the lattice of tilings 13 and 14 (period 4/√2 = 2√2), in units of 1/√2 and
/// folded about a square's centre: the distance from that centre, in [0, 2], and whether the
/// point was on its negative side.
fn inner_square_cell(v: f64) -> (f64, bool) {
    let v = wrap(v * SQRT_2, 4.0) - 2.0;
    (v.abs(), v < 0.0)
}

/// Where a point of the folded [`inner_square_cell`] lies.
enum InnerSquare {
    /// In the square, at this border distance (0 over its middle, 1 on its edge).
    Middle(f64),
    /// In the hexagon beside the square along x or along z: the distance across it,
    /// `2 |1.5 − v|`, and, where its slanted edge is near, `√2 |x − z|`.
    AlongX(f64, Option<f64>),
    AlongZ(f64, Option<f64>),
    /// Only a point that rounded onto the far end of the period.
    Outside,
}

fn inner_square_region(x: f64, z: f64) -> InnerSquare {
    let diagonal = || SQRT_2 * (x - z).abs();
    match x as i32 + (z as i32) * 2 {
        0 => {
            let x = (x - 0.5).max(0.0) * 2.0;
            let z = (z - 0.5).max(0.0) * 2.0;
            InnerSquare::Middle(x.max(z))
        }
        1 => InnerSquare::AlongX((1.5 - x).abs() * 2.0, (z > 0.5).then(diagonal)),
        2 => InnerSquare::AlongZ((1.5 - z).abs() * 2.0, (x > 0.5).then(diagonal)),
        3 if x > z => InnerSquare::AlongX((1.5 - x).abs() * 2.0, Some(diagonal())),
        3 => InnerSquare::AlongZ((1.5 - z).abs() * 2.0, Some(diagonal())),
        _ => InnerSquare::Outside,
    }
}

/// tiling 13: squares, each ringed by four elongated hexagons that join it to its neighbours
/// (period 2√2). Squares [0, ⅓], hexagons between squares along z [⅓, ⅔], along x [⅔, 1].
fn inner_squares(x: f64, z: f64) -> f64 {
    let (x, _) = inner_square_cell(x);
    let (z, _) = inner_square_cell(z);
    let band = |base: f64, across: f64, diagonal: Option<f64>| {
        let straight = (base + across) / 3.0;
        diagonal.map_or(straight, |d| straight.max((base + 1.0 - d) / 3.0))
    };
    match inner_square_region(x, z) {
        InnerSquare::Middle(d) => d / 3.0,
        InnerSquare::AlongX(across, diagonal) => band(2.0, across, diagonal),
        InnerSquare::AlongZ(across, diagonal) => band(1.0, across, diagonal),
        InnerSquare::Outside => 0.0,
    }
}

/// tiling 14: tiling 13 with each hexagon cut lengthwise into two trapezoids, told apart by
/// the side of the square they lie on, in fifths: +x side [0, ⅕], −x side [⅕, ⅖], −z side
/// [⅖, ⅗], +z side [⅗, ⅘]; squares just above ⅘ to 1.
fn inner_squares_5(x: f64, z: f64) -> f64 {
    let (x, x_low) = inner_square_cell(x);
    let (z, z_low) = inner_square_cell(z);
    let band = |base: f64, across: f64, diagonal: Option<f64>| {
        let d = diagonal.map_or(across, |d| across.max(1.0 - d));
        (d + base) / 5.0
    };
    match inner_square_region(x, z) {
        InnerSquare::Middle(d) => (4.000001 + d) / 5.0,
        InnerSquare::AlongX(across, diagonal) => {
            band(if x_low { 1.0 } else { 0.0 }, across, diagonal)
        }
        InnerSquare::AlongZ(across, diagonal) => {
            band(if z_low { 2.0 } else { 3.0 }, across, diagonal)
        }
        InnerSquare::Outside => 0.0,
    }
}

// ---------------------------------------------------------------------------------------------
// Triangles, lozenges, hexagons
// ---------------------------------------------------------------------------------------------

/// tiling 2: regular hexagons of side 1 (3 apart along x, √3 along z). 0 at the centre, 1 on
/// the edges.
fn hexagons(x: f64, z: f64) -> f64 {
    let mut x = wrap(x + 0.5, 3.0);
    let mut z = wrap(z, SQRT3);
    if z > HALF_SQRT3 {
        z = SQRT3 - z;
    }
    if x > 1.5 {
        x -= 1.5;
        z = HALF_SQRT3 - z;
    }
    if SQRT3 * x + z < HALF_SQRT3 {
        x = 0.5 - x;
        z = HALF_SQRT3 - z;
    }
    if x > 1.0 {
        x = 2.0 - x;
    }
    let across = 1.0 - (z / HALF_SQRT3);
    let slanted = 1.0 - ((SQRT3 * x + z - HALF_SQRT3) / SQRT3);
    across.max(slanted).clamp(0.0, 1.0)
}

/// tiling 3: equilateral triangles of side 1. Triangles pointing to +z [0, ½], to −z [½, 1].
fn triangles(x: f64, z: f64) -> f64 {
    let (distance, down) = unit_triangles(x, z, false);
    let band = if down { 1.0 } else { 0.0 };
    band / 2.0 + 0.5 * distance
}

/// tiling 4: lozenges (rhombuses of 60°, side 1) all lying the same way. 0 at the centre, 1 on
/// the edges.
fn lozenges(x: f64, z: f64) -> f64 {
    let mut x = wrap(x, 1.0);
    let mut z = wrap(z, SQRT3);
    if z > HALF_SQRT3 {
        z -= HALF_SQRT3;
        x += 0.5;
    }
    lozenge_distance(x, z)
}

/// tiling 5: lozenges in three orientations, three around each hexagon-shaped group. One
/// orientation per third of [0, 1].
fn rhombuses(x: f64, z: f64) -> f64 {
    let mut x = wrap(x + 0.5, 3.0);
    let mut z = wrap(z, SQRT3);
    let mut band = 0;
    if z > HALF_SQRT3 {
        z = SQRT3 - z;
        band = 2 - band;
    }
    if x > 1.5 {
        x -= 1.5;
        z = HALF_SQRT3 - z;
        band = 2 - band;
    }
    if x < 0.5 {
        x = 1.0 - x;
        band = 2 - band;
    }
    x -= 0.5;
    if x == 0.0 || z / x > SQRT3 {
        // Turn the upright lozenge by -60° onto the lying one.
        let turned_x = (x / 2.0) + (z * HALF_SQRT3);
        let turned_z = (z / 2.0) - (x * HALF_SQRT3);
        x = turned_x;
        z = turned_z;
        band = 1;
    }
    let value = lozenge_distance(x, z) / 3.0 + f64::from(band) / 3.0;
    value.clamp(0.0, 1.0)
}

/// tiling 9: hexagons of side 1 with two triangles between each three (the trihexagonal
/// tiling). Triangles pointing to +z [0, ⅓], to −z [⅓, ⅔], hexagons [⅔, 1].
fn hexagons_and_triangles(x: f64, z: f64) -> f64 {
    let mut x = wrap(x + 0.5, 2.0);
    let mut z = wrap(z, 2.0 * SQRT3);
    if z > SQRT3 {
        z -= SQRT3;
        x += if x < 1.0 { 1.0 } else { -1.0 };
    }
    let mut band = 0.0;
    if z > HALF_SQRT3 {
        z = SQRT3 - z;
        band = 1.0;
    }
    if x > 1.0 {
        x = 2.0 - x;
    }
    if SQRT3 * x + z < HALF_SQRT3 {
        let base = 1.0 - (z * 2.0 * SQRT3);
        let side = 1.0 + ((SQRT3 * x + z) - HALF_SQRT3) * SQRT3;
        (band + base.max(side)) / 3.0
    } else {
        hexagon_band(x, z, 2.0000001)
    }
}

/// Which way the snub hexagonal tiling turns.
#[derive(Clone, Copy, PartialEq)]
enum Hand {
    Right,
    Left,
}

/// tilings 19 and 20: the snub hexagonal tiling (each hexagon of side 1 ringed by triangles),
/// right-handed (19) and left-handed (20). Triangles pointing to +z [0, ⅓], to −z [⅓, ⅔],
/// hexagons [⅔, 1].
fn snub_hexagonal(x: f64, z: f64, hand: Hand) -> f64 {
    let period_z = 3.0 * HALF_SQRT3;
    // Each band of three triangle rows is shifted half a unit along x from the one below.
    let mut rows = c_int(z / HALF_SQRT3) / 3;
    if z < 0.0 {
        rows = rows.wrapping_sub(1);
    }
    let shift = f64::from(rows) / 2.0;
    let mut x = match hand {
        Hand::Right => x + shift,
        Hand::Left => x - shift,
    };
    let mut z = wrap(z, period_z);
    x += 7.0;
    x = wrap(x, 7.0);
    // Bring the 7-unit period's three hexagons onto the first one.
    match hand {
        Hand::Right => {
            if x > 4.5 && z > SQRT3 {
                x -= 4.5;
                z -= HALF_SQRT3;
            }
            if x > 5.0 && z < HALF_SQRT3 {
                x -= 5.0;
                z += SQRT3;
            }
            if x > 2.5 && z < SQRT3 {
                x -= 2.5;
                z += HALF_SQRT3;
            }
        }
        Hand::Left => {
            if x > 2.0 && z < HALF_SQRT3 {
                x -= 2.0;
                z += SQRT3;
            }
            if x > 4.5 && z < SQRT3 {
                x -= 4.5;
                z += HALF_SQRT3;
            }
            if x > 2.5 && z > SQRT3 {
                x -= 2.5;
                z -= HALF_SQRT3;
            }
        }
    }
    let mut down = false;
    let mut row = c_int(z / HALF_SQRT3);
    if row == 2 {
        row = 1;
        z = 2.0 * SQRT3 - z;
        down = true;
    }
    let in_triangles = row == 0 || x > 2.0 || z + SQRT3 * x < SQRT3 || SQRT3 * x - z > SQRT3;
    if in_triangles {
        let (distance, flipped) = unit_triangles(x, z, true);
        let band = if down != flipped { 1.0 } else { 0.0 };
        (band + distance) / 3.0
    } else {
        let z = z - HALF_SQRT3;
        let x = if x > 1.0 { 2.0 - x } else { x };
        hexagon_band(x, z, 2.000001)
    }
}

/// tiling 8: rows of unit squares between rows of triangles (the elongated triangular
/// tiling). Triangles pointing to +z [0, ⅓], to −z [⅓, ⅔], squares just above ⅔ to just
/// above 1.
fn squares_and_triangles(x: f64, z: f64) -> f64 {
    let mut x = wrap(x, 1.0);
    let mut z = wrap(z, 2.0 + SQRT3);
    if z > HALF_SQRT3 + 1.0 {
        z -= HALF_SQRT3 + 1.0;
        x += if x > 0.5 { -0.5 } else { 0.5 };
    }
    if x > 0.5 {
        x = 1.0 - x;
    }
    z -= 1.0;
    if z > 0.0 {
        let (x, z, flipped) = fold_triangle(x, z, true);
        let band = if flipped { 1.0 } else { 0.0 };
        (band + triangle_distance(x, z)) / 3.0
    } else {
        if z < -0.5 {
            z = -1.0 - z;
        }
        let across_x = (2.0 + 2.0 * SQRT3 * x.abs()).min(3.0);
        let across_z = (2.0 + 2.0 * SQRT3 * z.abs()).min(3.0);
        (5.0000001 - across_x.min(across_z)) / 3.0
    }
}

/// The geometry shared by tilings 16 and 17 (the rhombitrihexagonal tiling: hexagons of side
/// 1, each edge against a square, triangles in the gaps): the piece holding the point with
/// its border distance, and the mirrorings and turn that brought the point into the
/// reference twelfth.
struct RhombiCell {
    piece: RhombiPiece,
    mirror_x: i32,
    mirror_z: i32,
    turned: i32,
}

enum RhombiPiece {
    /// Distance to the edge, 0 on it, 1.5 and more in the middle.
    Hexagon(f64),
    /// 0 in the middle, 1 on the edges.
    Square(f64),
    /// 1 in the middle, 2 on the edges.
    Triangle(f64),
    None,
}

fn rhombi_cell(x: f64, z: f64) -> RhombiCell {
    let mut x = wrap(x + 0.5, 3.0 + SQRT3);
    let mut z = wrap(z, 2.0 * (1.0 + SQRT3));
    let (mut mirror_x, mut mirror_z, mut turned) = (0, 0, 0);
    if x > HALF_SQRT3 + 1.5 {
        x -= HALF_SQRT3 + 1.5;
        z += if z < SQRT3 + 1.0 {
            HALF_SQRT3 + 0.5
        } else {
            -(HALF_SQRT3 + 0.5)
        };
    }
    if z > SQRT3 + 1.0 {
        z -= SQRT3 + 1.0;
    }
    if z > 0.5 + HALF_SQRT3 {
        z = SQRT3 + 1.0 - z;
        mirror_z = 1 - mirror_z;
    }
    if x > 1.0 + HALF_SQRT3 {
        x = SQRT3 + 2.0 - x;
        mirror_x = 1 - mirror_x;
    }
    if SQRT3 * x + z < HALF_SQRT3 + 2.0 && x < 0.5 + HALF_SQRT3 {
        // Turn by 60° about (1 + √3/2, ½ + √3/2).
        z -= 0.5 + HALF_SQRT3;
        x -= 1.0 + HALF_SQRT3;
        let turned_x = (x / 2.0) - (z * HALF_SQRT3);
        let turned_z = (z / 2.0) + (x * HALF_SQRT3);
        z = turned_z + (0.5 + HALF_SQRT3);
        x = turned_x + (1.0 + HALF_SQRT3);
        turned = 1 - turned;
        if z < 0.0 {
            z = -z;
        }
        if x > 1.0 + HALF_SQRT3 {
            x = SQRT3 + 2.0 - x;
            mirror_x = 1 - mirror_x;
            mirror_z = 1 - mirror_z;
        }
    }
    let piece = if SQRT3 * x + z >= HALF_SQRT3 + 2.0 && z >= 0.5 {
        let z = (z - 0.5).abs();
        let x = (x - HALF_SQRT3).abs();
        let across = 2.0 * z * SQRT3;
        let slanted = (SQRT3 * x + z) * SQRT3 - 1.5;
        RhombiPiece::Hexagon(across.min(slanted))
    } else if z < 0.5 {
        if x > HALF_SQRT3 + 0.5 {
            let x = x - (HALF_SQRT3 + 0.5);
            let z = z - 0.5;
            let bottom = (1.0 + z * 2.0 * SQRT3).max(0.0);
            let side = (1.0 - x * 2.0 * SQRT3).max(0.0);
            RhombiPiece::Square(bottom.max(side))
        } else {
            let x = (x - (HALF_SQRT3 + 0.5)).abs();
            let slanted = (SQRT3 * z + x) * SQRT3 + 0.5;
            let upright = 2.0 - (x * 2.0 * SQRT3);
            RhombiPiece::Triangle(upright.max(slanted))
        }
    } else {
        RhombiPiece::None
    };
    RhombiCell {
        piece,
        mirror_x,
        mirror_z,
        turned,
    }
}

/// tiling 16: hexagons, squares and triangles (the rhombitrihexagonal tiling). Squares
/// [0, ⅓], triangles [⅓, ⅔], hexagons just above ⅔ to 1.
fn hexagons_squares_triangles(x: f64, z: f64) -> f64 {
    match rhombi_cell(x, z).piece {
        RhombiPiece::Hexagon(d) => (3.0 - d).max(2.0000001) / 3.0,
        RhombiPiece::Square(d) | RhombiPiece::Triangle(d) => d / 3.0,
        RhombiPiece::None => 0.0,
    }
}

/// tiling 17: tiling 16 with every tile told apart by orientation, in sixths: the three
/// square orientations [0, ⅙], just above ⅙ to ⅓ and just above ⅓ to ½, the two triangle
/// orientations [½, ⅔] and [⅔, ⅚], hexagons just above ⅚ to 1.
fn hexagons_squares_triangles_6(x: f64, z: f64) -> f64 {
    let cell = rhombi_cell(x, z);
    match cell.piece {
        RhombiPiece::Hexagon(d) => (6.0 - d).max(5.000001) / 6.0,
        RhombiPiece::Square(d) => {
            let parity = f64::from((cell.mirror_x + cell.mirror_z) % 2);
            (d + f64::from(cell.turned) * (1.000001 + parity)) / 6.0
        }
        RhombiPiece::Triangle(d) => {
            let base = if (cell.turned + cell.mirror_x) % 2 != 0 {
                2.0
            } else {
                3.0
            };
            (base + d) / 6.0
        }
        RhombiPiece::None => 0.0,
    }
}

/// tiling 7: octagons of side 1 with squares turned 45° between them (the truncated square
/// tiling, period 1 + √2). Squares [0, ½], octagons just above ½ to 1.
fn octagons_and_squares(x: f64, z: f64) -> f64 {
    let period = SQRT_2 + 1.0;
    let centre = FRAC_1_SQRT_2 + 0.5;
    let a = (wrap(x, period) - centre).abs();
    let b = (wrap(z, period) - centre).abs();
    let (far, near) = if b > a { (b, a) } else { (a, b) };
    if far + near < FRAC_1_SQRT_2 {
        return (far + near) / SQRT_2;
    }
    let straight = 1.0 - near;
    let diagonal = (SQRT_2 + FRAC_1_SQRT_2 - (far + near)) / SQRT_2;
    0.500000000001_f64.max(straight.max(diagonal))
}

/// tiling 21: squares and triangles, the squares turned alternately by ±15° (the snub square
/// tiling, period 1 + √3). The four triangle orientations take one sixth each of [0, ⅔], the
/// two square orientations just above ⅔ to ⅚ and just above ⅚ to 1.
fn snub_square(x: f64, z: f64) -> f64 {
    let period = 1.0 + SQRT3;
    let half = 0.5 + HALF_SQRT3;
    let mut x = wrap(x, period);
    let mut z = wrap(z, period);
    let mut odd = 0;
    let mut mirrored_x = false;
    if z > half {
        z = 1.0 + SQRT3 - z;
        odd = 1 - odd;
    }
    if x > half {
        x = 1.0 + SQRT3 - x;
        odd = 1 - odd;
        mirrored_x = true;
    }
    let flop_x = 2.0 * x + (SQRT3 - 1.0) * 2.0 * z / (SQRT3 + 1.0) > SQRT3;
    let flop_z = 2.0 * z * SQRT3 + (SQRT3 - 3.0) * 2.0 * x / (SQRT3 + 1.0) > SQRT3;
    let orientation = match (flop_x, flop_z) {
        (false, false) => 2 * i32::from(mirrored_x),
        (true, false) => {
            let o = if mirrored_x { 1 + 2 * odd } else { 3 - 2 * odd };
            (x, z) = (z, HALF_SQRT3 + 0.5 - x);
            o
        }
        (false, true) => {
            let o = if mirrored_x { 3 - 2 * odd } else { 1 + 2 * odd };
            (x, z) = (HALF_SQRT3 + 0.5 - z, x);
            o
        }
        (true, true) => {
            x = HALF_SQRT3 + 0.5 - x;
            z = HALF_SQRT3 + 0.5 - z;
            2 * i32::from(!mirrored_x)
        }
    };
    if x == 0.0 {
        x = 0.0;
        z = 0.0;
    }
    let edge = (z * 2.0 * SQRT3) - SQRT3 + x * 2.0;
    if edge < 0.0 {
        let across = -1.5 / SQRT3 * edge;
        let side = 2.0 * x * SQRT3;
        (f64::from(orientation) + 1.0 - across.min(side)) / 6.0
    } else {
        let d = (edge * (1.5 / SQRT3)).min(1.0);
        if odd != 0 {
            ((6.0 - d) / 6.0).clamp(5.000001 / 6.0, 1.0)
        } else {
            ((5.0 - d) / 6.0).clamp(4.000001 / 6.0, 5.0 / 6.0)
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Dodecagons
// ---------------------------------------------------------------------------------------------

/// tiling 22: dodecagons with triangles between them (the truncated hexagonal tiling).
/// Triangles of the two orientations [0, ⅓] and [⅓, ⅔], dodecagons just above ⅔ to just above
/// 1.
fn dodecagons_and_triangles(x: f64, z: f64) -> f64 {
    let mut x = wrap(x, 2.0 + SQRT3);
    let mut z = wrap(z, 3.0 + 2.0 * SQRT3);
    let mut toggled = 0;
    if z > SQRT3 + 1.5 {
        z -= SQRT3 + 1.5;
        x += (if x < 1.0 + HALF_SQRT3 { 1.0 } else { -1.0 }) * (1.0 + HALF_SQRT3);
    }
    if x > 1.0 + HALF_SQRT3 {
        x = 2.0 + SQRT3 - x;
    }
    if z > 1.0 + HALF_SQRT3 {
        z = 2.0 + SQRT3 - z;
        toggled = 1;
    }
    let mut slanted = x - HALF_SQRT3 - 0.5 + z * SQRT3;
    if slanted < 0.0 {
        // Mirror in the slanted line.
        let (old_x, old_z) = (x, z);
        x = (1.0 + SQRT3) / 4.0 + 0.5 * old_x - HALF_SQRT3 * old_z;
        z = (3.0 + SQRT3) / 4.0 - HALF_SQRT3 * old_x - 0.5 * old_z;
        slanted = -slanted;
    }
    let bottom = z * 3.0;
    let triangle = (z - HALF_SQRT3 - 0.5 + x * SQRT3) * SQRT3;
    let slanted = slanted * SQRT3;
    let upright = x * 3.0;
    if triangle < 0.0 {
        (triangle.max(-1.0) + f64::from(1 + toggled)) / 3.0
    } else {
        let d = bottom.min(slanted).min(triangle).min(upright).min(1.0);
        (3.0000001 - d) / 3.0
    }
}

/// The pieces of the dodecagon-hexagon-square tiling (tilings 23 and 24), each with its
/// border distance.
enum DodecaPiece {
    /// A dodecagon: distance from its edge, at most 1.
    Dodecagon(f64),
    /// The square above the dodecagon.
    UpperSquare(f64),
    /// A hexagon (the one beside or the one below), distance at most 1.
    Hexagon(f64),
    /// The slanted square.
    SlantedSquare(f64),
}

/// The truncated trihexagonal tiling (dodecagons of side 1, with hexagons and squares), folded
/// into its reference piece: the piece and whether x and z were mirrored on the way.
fn dodeca_hex_cell(x: f64, z: f64) -> (DodecaPiece, i32, i32) {
    let mut x = wrap(x, 3.0 + SQRT3);
    let mut z = wrap(z, 3.0 + 3.0 * SQRT3);
    let (mut mirror_x, mut mirror_z) = (0, 0);
    if z > 1.5 * SQRT3 + 1.5 {
        z -= 1.5 * SQRT3 + 1.5;
        x += (if x < 1.5 + HALF_SQRT3 { 1.0 } else { -1.0 }) * (1.5 + HALF_SQRT3);
    }
    if x > 1.5 + HALF_SQRT3 {
        x = 3.0 + SQRT3 - x;
        mirror_x = 1 - mirror_x;
    }
    if z > 1.0 + SQRT3 {
        z = 2.0 + 2.0 * SQRT3 - z;
        mirror_z = 1 - mirror_z;
    }
    if x - HALF_SQRT3 - 1.5 + z * SQRT3 < 0.0 {
        // Mirror in the slanted line.
        let (old_x, old_z) = (x, z);
        x = (3.0 + SQRT3) / 4.0 + 0.5 * old_x - HALF_SQRT3 * old_z;
        z = (3.0 + 3.0 * SQRT3) / 4.0 - HALF_SQRT3 * old_x - 0.5 * old_z;
    }
    let slanted = x - HALF_SQRT3 - 2.5 + z * SQRT3;
    let bottom = (z * 2.0) - SQRT3;
    let side = z - 1.5 * SQRT3 - 0.5 + x * SQRT3;
    let upright = (x - 0.5) * 2.0;
    let piece = if slanted >= 0.0 && bottom >= 0.0 && side >= 0.0 && upright >= 0.0 {
        DodecaPiece::Dodecagon(bottom.min(slanted).min(side).min(upright).min(1.0))
    } else {
        let top = 2.0 * z - 2.0 * SQRT3 - 1.0;
        if top >= 0.0 {
            DodecaPiece::UpperSquare(top.min(-upright))
        } else {
            let lower = SQRT3 * x - z - HALF_SQRT3 + 0.5;
            let upper = lower - 2.0;
            match (lower >= 0.0, upper >= 0.0) {
                (false, false) => DodecaPiece::Hexagon((-lower).min(-side).min(-top).min(1.0)),
                (true, true) => DodecaPiece::Hexagon(upper.min(-bottom).min(1.0)),
                _ => DodecaPiece::SlantedSquare(lower.min(-slanted).min(-upper)),
            }
        }
    };
    (piece, mirror_x, mirror_z)
}

/// tiling 23: dodecagons, hexagons and squares (the truncated trihexagonal tiling). Hexagons
/// [0, ⅓], squares [⅓, ⅔], dodecagons just above ⅔ to 1.
fn dodecagons_hexagons_squares(x: f64, z: f64) -> f64 {
    let value = match dodeca_hex_cell(x, z).0 {
        DodecaPiece::Dodecagon(d) => 3.000001 - d,
        DodecaPiece::UpperSquare(d) | DodecaPiece::SlantedSquare(d) => 2.0 - d,
        DodecaPiece::Hexagon(d) => 1.0 - d,
    };
    value / 3.0
}

/// tiling 24: tiling 23 with the squares told apart by orientation, in fifths: hexagons
/// [0, ⅕], upright squares [⅕, ⅖], the two slanted square orientations [⅖, ⅗] and [⅗, ⅘],
/// dodecagons just above ⅘ to 1.
fn dodecagons_hexagons_squares_5(x: f64, z: f64) -> f64 {
    let (piece, mirror_x, mirror_z) = dodeca_hex_cell(x, z);
    let value = match piece {
        DodecaPiece::Dodecagon(d) => 5.000001 - d,
        DodecaPiece::UpperSquare(d) => 2.0 - d,
        DodecaPiece::Hexagon(d) => 1.0 - d,
        DodecaPiece::SlantedSquare(d) => f64::from((mirror_z + mirror_x) % 2) + 3.0 - d,
    };
    value / 5.0
}

// ---------------------------------------------------------------------------------------------
// Penrose tilings
// ---------------------------------------------------------------------------------------------

/// Rotates (x, z) by the angle whose cosine and sine are given (towards +z).
fn rotate(x: f64, z: f64, cos: f64, sin: f64) -> (f64, f64) {
    (x * cos - z * sin, z * cos + x * sin)
}

/// Folds a point into the wedge of ±36° around +x, by the five-fold rotational and the mirror
/// symmetry of a pentagon centred on the origin; `r` is the distance from the origin.
fn pentagon_fold(x: f64, z: f64, r: f64) -> (f64, f64) {
    let z = z.abs();
    if x < r * COS36 {
        let (sin, cos) = if x < r * COS108 {
            (SIN144, COS144)
        } else {
            (SIN72, COS72)
        };
        // Turn back by 144° or by 72°.
        let (x, z) = rotate(x, z, cos, -sin);
        (x, z.abs())
    } else {
        (x, z)
    }
}

/// [`pentagon_fold`] about the point's own distance from the origin.
fn pentagon_fold_here(x: f64, z: f64) -> (f64, f64) {
    pentagon_fold(x, z, (x * x + z * z).sqrt())
}

/// How many inflation steps a point at `distance` from the centre needs (each step scales
/// by the ratio whose logarithm is `ln_ratio`); 0 near the centre.
fn inflation_steps(distance: f64, ln_ratio: f64) -> i32 {
    c_int((distance.ln() / ln_ratio).ceil()).max(0)
}

/// The two Penrose tilings made of triangle halves.
#[derive(Clone, Copy, PartialEq)]
enum Penrose {
    /// P2: kites and darts.
    KitesAndDarts,
    /// P3: fat and thin rhombs.
    Rhombs,
}

/// The two Robinson-like half tiles the kite-and-dart and rhomb tilings deflate into.
#[derive(Clone, Copy)]
enum HalfTile {
    Kite,
    Dart,
}

/// tilings 26 and 27: the Penrose tilings P2 (26: kites [0, ½), darts (½, 1]) and P3 (27:
/// fat rhombs [0, ½), thin rhombs (½, 1]), with five-fold symmetry about the origin, where the
/// value is 1: P2 has a star of five darts there, P3 a star of five fat rhombs.
fn penrose(x: f64, z: f64, kind: Penrose) -> f64 {
    let r = (x * x + z * z).sqrt();
    if r <= 1e-10 {
        return 1.0;
    }
    let (mut x, mut z) = pentagon_fold(x, z, r);
    if kind == Penrose::Rhombs {
        x *= INV_PHI;
        z *= INV_PHI;
    }
    let reach = (SIN108 * x - COS108 * z).abs() / COS18;
    let steps = inflation_steps(reach, LN_PHI_SQUARED);
    let scale = INV_PHI_SQUARED.powf(f64::from(steps));
    x *= scale;
    z *= scale;
    if steps % 2 != 0 {
        (x, z) = rotate(x, z, COS36, -SIN36);
        z = z.abs();
    }
    penrose_half_tiles(x, z, 2 * steps, kind)
}

/// Deflates the half kite containing (x, z) `depth` times, then gives the border value of
/// the half tile reached.
fn penrose_half_tiles(x: f64, z: f64, depth: i32, kind: Penrose) -> f64 {
    let (mut x, mut z) = (x, z);
    let mut tile = HalfTile::Kite;
    for _ in 0..depth {
        z = z.abs();
        match tile {
            HalfTile::Kite => {
                if z < (x - INV_PHI) * TAN144 {
                    tile = HalfTile::Dart;
                } else {
                    (x, z) = rotate(x - COS36, z - SIN36, COS108, SIN108);
                }
            }
            HalfTile::Dart => {
                if z < (x - INV_PHI) * TAN108 {
                    tile = HalfTile::Kite;
                    (x, z) = rotate(x, z, COS36, -SIN36);
                } else {
                    (x, z) = rotate(x - 1.0, z, COS144, -SIN144);
                }
            }
        }
        x *= PHI;
        z *= PHI;
    }
    let z = z.abs();
    let below_half = |a: f64, b: f64| {
        (0.5 - a / 2.0)
            .max((0.5 - b / 2.0).max(0.0))
            .min(0.5 - BAND_MARGIN)
    };
    let above_half = |a: f64, b: f64| (1.0 - a / 2.0).max((1.0 - b / 2.0).max(0.5 + BAND_MARGIN));
    match (kind, tile) {
        (Penrose::Rhombs, HalfTile::Kite) => {
            let mid = (SIN72 * (x - INV_PHI) - COS72 * z).abs() * 5.55;
            if z < (x - INV_PHI) * TAN72 {
                let far = (SIN108 * (x - 1.0) - COS108 * z).abs() * 5.55;
                above_half(mid, far)
            } else {
                below_half(z.abs() * 5.55, mid)
            }
        }
        (Penrose::Rhombs, HalfTile::Dart) => {
            let near = (SIN36 * x - COS36 * z).abs() * 5.55;
            let far = (SIN144 * (x - 1.0) - COS144 * z).abs() * 5.55;
            below_half(near, far)
        }
        (Penrose::KitesAndDarts, HalfTile::Kite) => {
            let near = (SIN36 * x - COS36 * z).abs() * 4.46;
            let far = (SIN108 * (x - 1.0) - COS108 * z).abs() * 4.46;
            below_half(near, far)
        }
        (Penrose::KitesAndDarts, HalfTile::Dart) => {
            let axis = z.abs() * 4.46;
            let far = (SIN144 * (x - 1.0) - COS144 * z).abs() * 4.46;
            above_half(axis, far)
        }
    }
}

/// The tiles of the pentagon Penrose tiling P1. The three kinds of pentagon differ by the
/// tiles they are cut into when deflated; the flags say from which part of its parent a tile
/// (or the part of it in hand) was cut, which decides how it deflates in turn.
#[derive(Clone, Copy)]
enum P1Tile {
    /// The first kind of pentagon, the one at the centre.
    Pentagon1,
    /// The second kind of pentagon; `in_quad` for the quadrilateral part.
    Pentagon2 { in_quad: bool },
    /// The third kind of pentagon; `in_wedge` for the wedge part.
    Pentagon3 { in_wedge: bool },
    /// A pentagram.
    Star,
    /// A boat (three points of a star).
    Boat { in_wedge: bool },
    /// A diamond (a thin rhomb); `side_a` for one of its two halves.
    Diamond { side_a: bool },
}

/// Distance from a folded pentagon's edge, scaled for the band.
fn pentagon_edge_distance(x: f64) -> f64 {
    (x - 0.5 / TAN36).abs() * 5.55 * INV_PHI
}

/// Distance from a star point's edge, scaled for the band.
fn star_edge_distance(x: f64, z: f64) -> f64 {
    (SIN162 * (x - PHI * 0.5 / SIN36) - COS162 * z).abs() * 5.55 * INV_PHI
}

/// `v` held within [`low`, `high`], the part of a band a tile may use.
fn in_band(v: f64, low: f64, high: f64) -> f64 {
    v.clamp(low, high)
}

/// tiling 25: the Penrose tiling P1 (pentagons, stars, boats and diamonds) with a pentagon
/// centred on the origin, where the value is 1. The six kinds of tile take the six sixths:
/// the three kinds of pentagon [0, ⅙), (⅙, ⅓) and (⅓, ½), stars (½, ⅔), boats (⅔, ⅚) and
/// diamonds (⅚, 1).
fn penrose_pentagons(x: f64, z: f64) -> f64 {
    let r = (x * x + z * z).sqrt();
    if r <= 1e-10 {
        return 1.0;
    }
    let (x, z) = pentagon_fold(x, z, r);
    let steps = inflation_steps(x * 2.0 * TAN36, LN_PHI_FOURTH);
    let scale = (INV_PHI_SQUARED * INV_PHI_SQUARED).powf(f64::from(steps));
    penrose_p1_tiles(x * scale, z * scale, 4 * steps)
}

/// Deflates the P1 pentagon containing (x, z) `depth` times, then gives the band value of the
/// tile reached.
fn penrose_p1_tiles(x: f64, z: f64, depth: i32) -> f64 {
    let (mut x, mut z) = (x, z);
    let mut tile = P1Tile::Pentagon1;
    let mut depth = depth;
    loop {
        z = z.abs();
        if matches!(tile, P1Tile::Pentagon1) {
            (x, z) = pentagon_fold_here(x, z);
        }
        if depth <= 0 {
            break;
        }
        depth -= 1;
        (tile, x, z) = deflate_p1(tile, x, z);
        x *= PHI;
        z *= PHI;
    }
    let sixth = |k: f64| k / 6.0;
    match tile {
        P1Tile::Pentagon1 => {
            let d = pentagon_edge_distance(x);
            in_band(1.0 / 6.0 - d / 6.0, 0.0, 1.0 / 6.0 - BAND_MARGIN)
        }
        P1Tile::Pentagon2 { .. } | P1Tile::Pentagon3 { .. } => {
            let k = if matches!(tile, P1Tile::Pentagon2 { .. }) {
                2.0
            } else {
                3.0
            };
            let (x, _) = pentagon_fold_here(x, z);
            let d = pentagon_edge_distance(x);
            in_band(
                sixth(k) - d / 6.0,
                sixth(k - 1.0) + BAND_MARGIN,
                sixth(k) - BAND_MARGIN,
            )
        }
        P1Tile::Star => {
            let d = star_edge_distance(x, z);
            in_band(
                4.0 / 6.0 - d / 6.0,
                3.0 / 6.0 + BAND_MARGIN,
                4.0 / 6.0 - BAND_MARGIN,
            )
        }
        P1Tile::Boat { .. } => {
            let keel = (x - INV_PHI * 0.5 * COS72 / SIN36).abs() * 5.55 * INV_PHI;
            let (x, z) = pentagon_fold_here(-x, z);
            let point = star_edge_distance(x, z);
            let v = (5.0 / 6.0 - keel / 6.0).max(5.0 / 6.0 - point / 6.0);
            in_band(v, 4.0 / 6.0 + BAND_MARGIN, 5.0 / 6.0 - BAND_MARGIN)
        }
        P1Tile::Diamond { .. } => {
            let d = (SIN18 * (x + INV_PHI * 0.5 / SIN36) - COS18 * z).abs() * 5.55 * INV_PHI;
            in_band(1.0 - d / 6.0, 5.0 / 6.0 + BAND_MARGIN, 1.0 - BAND_MARGIN)
        }
    }
}

/// One deflation step of the P1 tiling: the sub-tile of `tile` holding (x, z) (already
/// folded as the tile requires), and the point in that sub-tile's frame before scaling by φ.
fn deflate_p1(tile: P1Tile, x: f64, z: f64) -> (P1Tile, f64, f64) {
    match tile {
        P1Tile::Pentagon1 => {
            if z < (x - 0.5 / TAN36) * TAN54 + 0.5 {
                let x = x - 0.5 / TAN36 - INV_PHI * 0.5 * COS72 / SIN36;
                (P1Tile::Pentagon2 { in_quad: false }, x, z)
            } else {
                let (x, z) = rotate(x, z, COS36, -SIN36);
                (P1Tile::Star, x, z)
            }
        }
        P1Tile::Pentagon2 { in_quad: true } => {
            let corner = INV_PHI_SQUARED * 0.5 / SIN36;
            if z < (x - corner) * TAN54 {
                (P1Tile::Pentagon1, x - 0.5 / SIN36, z)
            } else if z < (x - corner) * TAN162 {
                (P1Tile::Diamond { side_a: true }, -x, z)
            } else {
                let turned_x = x * COS108 - z * SIN108 + INV_PHI * 0.5 / SIN36;
                let turned_z = z * COS108 + x * SIN108;
                (P1Tile::Pentagon2 { in_quad: true }, turned_x, turned_z)
            }
        }
        P1Tile::Pentagon2 { in_quad: false } => {
            if z < (x + 0.5 / SIN36) * TAN18 {
                let x = x + 0.5 / SIN36 - INV_PHI_SQUARED * 0.5 / SIN36;
                (P1Tile::Diamond { side_a: false }, x, z)
            } else {
                let turned_x = -(x * COS36 + z * SIN36) - COS72 * 0.5 / SIN36;
                let turned_z = (z * COS36 - x * SIN36) - SIN72 * 0.5 / SIN36;
                (P1Tile::Pentagon3 { in_wedge: false }, turned_x, turned_z)
            }
        }
        P1Tile::Pentagon3 { in_wedge } => {
            let wedge_tip = INV_PHI_SQUARED * 0.5 * COS72 / SIN36;
            if in_wedge && x > wedge_tip {
                let x = -(x - wedge_tip - INV_PHI * 0.5 / TAN36);
                (P1Tile::Pentagon2 { in_quad: true }, x, z)
            } else if !in_wedge && x < 0.5 * COS108 / SIN36 {
                let turned_x = x * COS144 + z * SIN144 - 0.5 / SIN36;
                let turned_z = z * COS144 - x * SIN144;
                (P1Tile::Pentagon2 { in_quad: false }, turned_x, turned_z)
            } else if !in_wedge && z > (x - INV_PHI_SQUARED * 0.5 / SIN36) * TAN126 {
                let turned_x = -(x * COS36 - z * SIN36) - COS72 * 0.5 / SIN36;
                let turned_z = (z * COS36 + x * SIN36) - SIN72 * 0.5 / SIN36;
                (P1Tile::Pentagon3 { in_wedge: false }, turned_x, turned_z)
            } else {
                (P1Tile::Boat { in_wedge }, x, z)
            }
        }
        P1Tile::Star => {
            if x < INV_PHI * 0.5 / TAN36 {
                (P1Tile::Pentagon1, x, z)
            } else {
                let x = -(x - INV_PHI / TAN36);
                (P1Tile::Pentagon3 { in_wedge: true }, x, z)
            }
        }
        P1Tile::Boat { in_wedge } => {
            if in_wedge && x > PHI * 0.5 * COS108 / SIN36 {
                (P1Tile::Pentagon1, -x, z)
            } else {
                let (x, z) = if in_wedge {
                    (x, z)
                } else {
                    rotate(x, z, COS72, SIN72)
                };
                (P1Tile::Pentagon3 { in_wedge: true }, x + 0.5 / SIN36, z)
            }
        }
        P1Tile::Diamond { side_a: true } => (P1Tile::Pentagon1, x, z),
        P1Tile::Diamond { side_a: false } => (P1Tile::Pentagon3 { in_wedge: true }, x, z),
    }
}

#[cfg(test)]
mod tests {
    use super::tiling;

    // The expected values are POV-Ray 3.7.0.10's, printed by `function { pigment { tiling N
    // … } }` (at frequency 1 and 65536, read back through a colour map) and rounded to 12
    // decimals.

    fn check(n: i32, p: [f64; 3], expected: f64) {
        let v = tiling(n, p);
        assert!(
            (v - expected).abs() < 1e-9,
            "tiling {n} at {p:?}: {v} (POV-Ray: {expected})"
        );
    }

    const A: [f64; 3] = [-4.832643475209773, -1.315883105115243, -7.352127622918218];
    const B: [f64; 3] = [-343.1511283604831, -0.6539304123361847, 951.0267807326486];
    const C: [f64; 3] = [1.5841960494926717, -3.383121760706318, -9.017594777195276];
    const GRID: [f64; 3] = [-7.5, 0.3, 7.5];

    #[test]
    fn hexagons() {
        check(2, A, 0.922603662582);
        check(2, GRID, 0.830127018922);
        check(2, B, 0.226696223021);
    }

    #[test]
    fn rhombuses() {
        check(5, A, 0.948402441722);
        check(
            5,
            [-0.45710678118654746, 0.0, -4.330127018922193],
            0.638071187458,
        );
        check(5, B, 0.616293001370);
    }

    #[test]
    fn squares_and_triangles() {
        check(8, C, 0.902778809655);
        check(8, [-5.75, 0.0, 4.82842712474619], 0.222047548001);
        check(
            8,
            [-17.40980570846736, 0.0, -12.648964251512034],
            0.895852636342,
        );
    }

    #[test]
    fn square_and_mirrored_rectangles() {
        check(12, A, 0.221762316807);
        check(12, GRID, 0.0);
        check(12, B, 0.648812844901);
        // On a line of the period grid POV-Ray's tile table overflows: 7/3, which its wave
        // turns into 0.33331.
        check(12, [6.0, 0.0, -5.5], 7.0 / 3.0);
    }

    #[test]
    fn hexagons_squares_triangles_6() {
        check(
            17,
            [-2.001123058911812, -4.898308305429317, 7.804956222089835],
            0.219843354678,
        );
        check(
            17,
            [-14.594869896942175, 0.0, -2.82842712474619],
            0.833333500000,
        );
        check(17, B, 0.491469141482);
    }

    #[test]
    fn snub_square() {
        check(21, A, 0.666666833333);
        check(
            21,
            [-0.45710678118654746, 0.0, -4.330127018922193],
            0.954459311299,
        );
        check(
            21,
            [-17.40980570846736, 0.0, -12.648964251512034],
            0.972021822569,
        );
    }

    #[test]
    fn dodecagons_hexagons_squares_5() {
        check(24, C, 0.911288257720);
        check(
            24,
            [-1.9760012358226797, 1.0, -24.24871130596428],
            0.056647365935,
        );
        check(24, A, 0.062390080085);
    }

    #[test]
    fn penrose() {
        let near = [0.8972674070417165, 0.3, 0.5491573260545671];
        check(25, near, 0.489791610350);
        check(
            25,
            [-17.40980570846736, 0.0, -12.648964251512034],
            0.016174721590,
        );
        check(25, B, 0.635297787179);
        check(26, A, 0.237825073242);
        check(26, near, 0.839452389061);
        check(27, near, 0.041391235162);
        check(27, C, 0.235166303795);
        check(27, B, 0.332916539049);
        // The centre.
        for n in 25..=27 {
            check(n, [0.0, 5.0, 0.0], 1.0);
        }
    }

    #[test]
    fn y_plays_no_part() {
        for n in 1..=27 {
            let v = tiling(n, [2.345, 0.0, -3.21]);
            for y in [-1000.0, -1.0, 0.5, 1e9] {
                assert_eq!(tiling(n, [2.345, y, -3.21]), v, "tiling {n}, y = {y}");
            }
        }
    }

    #[test]
    fn number_keeps_its_low_byte() {
        // POV-Ray reads `tiling 261` and `tiling -251` as `tiling 5`.
        check(261, A, 0.948402441722);
        check(-251, A, 0.948402441722);
        assert_eq!(tiling(283, C), tiling(27, C));
    }
}
