//! POV-Ray 3.7's `pavement` pattern: the (x, z) plane paved with polyforms — tiles made of
//! 1 to 6 equal squares, triangles or hexagons — with a value that is 0 deep inside a tile
//! and rises to 1 on its outline.
//!
//! The plane is cut into cells of a regular grid (unit squares, or equilateral triangles of
//! side 1). Each variant of the pattern gives every cell, by its integer grid coordinates, a
//! *code*: a set of bits saying which sides of the cell lie on a tile's outline and how the
//! corners are treated. The value at a point is then a function of its code and of its
//! position inside the cell, under the `interior` (inner corners), `exterior` (outer corners)
//! and `form` (quarter tiles) options.
//!
//! Everything follows POV-Ray 3.7.0.10 (`pavement_pattern` and the parser's checks of its
//! keywords), with the floating-point operations in the same order so that the values on
//! and near the outlines agree.

use std::fmt;

/// √3 (POV-Ray's `SQRT3`).
const SQRT3: f64 = 1.732_050_807_568_877_2;
/// √3 / 2, the height of a triangle cell (POV-Ray's `SQRT3_2`).
const SQRT3_2: f64 = 0.866_025_403_784_438_6;

/// `pavement`'s parameters; `Default` gives POV-Ray's defaults (`number_of_sides 3`,
/// `number_of_tiles 1`, `pattern 1`, `exterior 0`, `interior 0`, `form 0`).
///
/// POV-Ray stores each keyword's value as an unsigned byte (see [`parameter_byte`]), so the
/// fields are bytes too; [`Pavement::checked`] applies the parser's checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pavement {
    /// `number_of_sides`: 3 (triangles), 4 (squares) or 6 (hexagons).
    pub sides: u8,
    /// `number_of_tiles`: cells per tile, 1 ..= 6 (1 ..= 5 for hexagons).
    pub tiles: u8,
    /// `pattern`: which of the shapes with that many cells, from 1 (see [`max_pattern`]).
    pub pattern: u8,
    /// `exterior`: outer corners sharp (0), cut (1) or rounded (2). Hexagons ignore it.
    pub exterior: u8,
    /// `interior`: inner corners sharp (0), cut (1) or rounded (2).
    pub interior: u8,
    /// `form`: how cells that are a quarter of a tile's bend are drawn: sharp (0), cut (1),
    /// rounded (2); squares also have 3 (no special treatment).
    pub form: u8,
}

impl Default for Pavement {
    fn default() -> Self {
        Pavement {
            sides: 3,
            tiles: 1,
            pattern: 1,
            exterior: 0,
            interior: 0,
            form: 0,
        }
    }
}

/// Why POV-Ray's parser rejects a `pavement` (its messages, from [`fmt::Display`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PavementError {
    /// `number_of_sides` is not 3, 4 or 6.
    Sides,
    /// `number_of_tiles` is 0 or more than the shape allows (the payload is `number_of_sides`).
    Tiles(u8),
    /// `pattern` is 0 or more than the shape allows (the payload is `number_of_sides`).
    Pattern(u8),
}

impl fmt::Display for PavementError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            PavementError::Sides => write!(f, "number_of_sides of pavement must be 3, 4 or 6."),
            PavementError::Tiles(sides) => write!(
                f,
                "number_of_tiles of pavement must be between 1 and {}.",
                variants_of(sides).len()
            ),
            PavementError::Pattern(sides) => {
                let maxima: Vec<String> = variants_of(sides)
                    .iter()
                    .map(|group| group.len().to_string())
                    .collect();
                write!(
                    f,
                    "pattern value for pavement is out of range. max per tile:({})",
                    maxima.join(",")
                )
            }
        }
    }
}

impl std::error::Error for PavementError {}

/// The byte POV-Ray keeps of a number given to one of `pavement`'s keywords: the number
/// truncated towards zero to a 32-bit integer, of which the low 8 bits are kept (so `257`
/// and `-255` are 1, `1.9` is 1, `-1` is 255); numbers outside the 32-bit range (and NaN)
/// give 0. This is what the x86-64 build of POV-Ray 3.7.0 does with its
/// `(unsigned char)` conversion.
pub fn parameter_byte(value: f64) -> u8 {
    if value.is_nan() || value >= 2_147_483_648.0 || value <= -2_147_483_649.0 {
        0
    } else {
        value.trunc() as i32 as u8
    }
}

/// The largest `pattern` for `sides` (3, 4, 6) and `tiles`, or `None` if POV-Ray accepts
/// no such combination.
pub fn max_pattern(sides: u8, tiles: u8) -> Option<u8> {
    let families = match sides {
        3 | 4 | 6 => variants_of(sides),
        _ => return None,
    };
    let group = families.get(usize::from(tiles).checked_sub(1)?)?;
    Some(group.len() as u8)
}

impl Pavement {
    /// The parameters as POV-Ray's parser leaves them, or the error it stops with.
    ///
    /// `interior` and `exterior` are taken modulo 3 and `form` modulo 4 for squares and
    /// modulo 3 otherwise (so `exterior 4` is `exterior 1`); `number_of_sides` must be 3, 4
    /// or 6, `number_of_tiles` 1 ..= 6 (1 ..= 5 for hexagons), and `pattern` from 1 to
    /// [`max_pattern`]: anything else is a parse error.
    pub fn checked(self) -> Result<Pavement, PavementError> {
        if !matches!(self.sides, 3 | 4 | 6) {
            return Err(PavementError::Sides);
        }
        let max = max_pattern(self.sides, self.tiles).ok_or(PavementError::Tiles(self.sides))?;
        if self.pattern == 0 || self.pattern > max {
            return Err(PavementError::Pattern(self.sides));
        }
        let forms = if self.sides == 4 { 4 } else { 3 };
        Ok(Pavement {
            interior: self.interior % 3,
            exterior: self.exterior % 3,
            form: self.form % forms,
            ..self
        })
    }

    /// The pattern's value at `p` = (x, y, z), in [0, 1]; only x and z matter.
    ///
    /// The parameters should be [`checked`](Pavement::checked) ones. Others never reach
    /// POV-Ray's pattern code, which would read its tables out of bounds; here a
    /// `number_of_sides` other than 4 or 6 means triangles (as in POV-Ray), an unknown
    /// `number_of_tiles` means 1 and an unknown `pattern` means 1, and options out of range
    /// are ignored like POV-Ray's switches do (except that squares treat any `interior`
    /// above 2 as 0).
    pub fn value(&self, p: [f64; 3]) -> f64 {
        let [x, _, z] = p;
        match self.sides {
            4 => self.square_value(x, z),
            6 => self.triangle_value(x, z, &HEXAGON_VARIANTS, 0),
            _ => self.triangle_value(x, z, &TRIANGLE_VARIANTS, self.exterior),
        }
    }

    /// The code of the cell at integer coordinates (`column`, `row`) in `families`.
    fn cell_code(&self, families: &[&[Variant]], column: i64, row: i64) -> u16 {
        let group = families
            .get(usize::from(self.tiles).wrapping_sub(1))
            .unwrap_or(&families[0]);
        let variant = group
            .get(usize::from(self.pattern).wrapping_sub(1))
            .unwrap_or(&group[0]);
        variant.code(column, row)
    }

    fn square_value(&self, x: f64, z: f64) -> f64 {
        let code = self.cell_code(&SQUARE_VARIANTS, grid_index(x), grid_index(z));
        let cell = SquareCell::new(x - x.floor(), z - z.floor());

        let quarter = SquareCorner::ALL
            .into_iter()
            .find(|corner| code & corner.quarter_mask() == corner.quarter_mask());
        if let Some(value) = quarter.and_then(|corner| cell.quarter(corner, self.form)) {
            return value;
        }

        let mut value = 0.0;
        for (bit, side) in [
            (SQUARE_NORTH, cell.north),
            (SQUARE_EAST, cell.east),
            (SQUARE_SOUTH, cell.south),
            (SQUARE_WEST, cell.west),
        ] {
            if code & bit != 0 {
                value = max(value, side);
            }
        }
        for corner in SquareCorner::ALL {
            if code & corner.inner_bit() != 0 {
                value = max(value, cell.inner_corner(corner, self.interior));
            }
            if code & corner.outer_mask() == corner.outer_mask() {
                if let Some(corner_value) = cell.outer_corner(corner, self.exterior) {
                    value = max(value, corner_value);
                }
            }
        }
        value
    }

    fn triangle_value(&self, x: f64, z: f64, families: &[&[Variant]], exterior: u8) -> f64 {
        let cell = TriangleCell::locate(x, z);
        let code = self.cell_code(families, cell.column, cell.row);
        let (x, z) = (cell.x, cell.z);

        // From 0 at the centre of the cell to 1 on its west side, east side and base.
        let sides = [
            1.0 - (SQRT3 * x - z).abs() * SQRT3,
            1.0 - (SQRT3 * (1.0 - x) - z).abs() * SQRT3,
            1.0 - z * 2.0 * SQRT3,
        ];
        let mut value = 0.0;
        for (bit, side) in [TRIANGLE_WEST_SIDE, TRIANGLE_EAST_SIDE, TRIANGLE_BASE]
            .into_iter()
            .zip(sides)
        {
            if code & bit != 0 {
                value = max(value, side);
            }
        }

        let zones = Zones::new(x, z);
        for vertex in Vertex::ALL {
            if vertex.is_inner(code) {
                if let Some(corner_value) = vertex.inner_corner(x, z, &zones, self.interior) {
                    value = max(value, corner_value);
                }
            }
        }

        // Unlike the rest, an outer corner replaces the value found so far.
        let (dx, dz) = (x - 0.5, z - SQRT3_2 / 3.0);
        match exterior {
            1 => {
                for vertex in Vertex::OUTER_ORDER {
                    let [a, b] = vertex.sides();
                    let mask = vertex.outer_mask();
                    if code & mask == mask && sides[a] >= 0.0 && sides[b] >= 0.0 {
                        value = min(1.0, vertex.cut_outer_corner(dx, dz));
                    }
                }
            }
            2 => {
                let rounded = Vertex::ALL.into_iter().any(|vertex| {
                    let mask = vertex.outer_mask();
                    code & mask == mask && zones.closed(vertex)
                });
                if rounded {
                    value = min(1.0, 2.0 * SQRT3 * (dx * dx + dz * dz).sqrt());
                }
            }
            _ => {}
        }

        if matches!(self.form, 1 | 2) {
            let quarter = TRIANGLE_QUARTERS
                .iter()
                .find(|quarter| code & quarter.mask == quarter.mask && zones.open(quarter.zone));
            if let Some(quarter) = quarter {
                if self.form == 1 {
                    return min((quarter.sign * zones.d[quarter.line]) * 2.0, 1.0);
                }
                let (cx, cz) = quarter.centre.position();
                let (dx, dz) = (x - cx, z - cz);
                let ring = 2.0 * SQRT3 * ((dx * dx + dz * dz).sqrt() - SQRT3 / 3.0);
                return min(max(ring, 0.0), 1.0);
            }
        }
        value
    }
}

/// C++'s `std::max`, which POV-Ray uses (the first argument on ties and NaN).
fn max(a: f64, b: f64) -> f64 {
    if a < b { b } else { a }
}

/// C++'s `std::min`.
fn min(a: f64, b: f64) -> f64 {
    if b < a { b } else { a }
}

/// The integer grid coordinate of `t` (POV-Ray converts `floor` to a `long`).
fn grid_index(t: f64) -> i64 {
    t.floor() as i64
}

// The side bits of a square cell's code (x grows to the east, z to the north): the side is
// on a tile's outline.
const SQUARE_NORTH: u16 = 0x01;
const SQUARE_EAST: u16 = 0x02;
const SQUARE_SOUTH: u16 = 0x04;
const SQUARE_WEST: u16 = 0x08;

/// A corner of a square cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SquareCorner {
    NorthWest,
    NorthEast,
    SouthEast,
    SouthWest,
}

impl SquareCorner {
    /// In the order POV-Ray looks for a quarter tile.
    const ALL: [SquareCorner; 4] = [
        SquareCorner::NorthWest,
        SquareCorner::NorthEast,
        SquareCorner::SouthEast,
        SquareCorner::SouthWest,
    ];

    /// The bit of an inner corner of a tile here.
    fn inner_bit(self) -> u16 {
        match self {
            SquareCorner::NorthWest => 0x10,
            SquareCorner::NorthEast => 0x20,
            SquareCorner::SouthEast => 0x40,
            SquareCorner::SouthWest => 0x80,
        }
    }

    /// The two sides that meet here: with both on the outline, an outer corner of a tile.
    fn outer_mask(self) -> u16 {
        match self {
            SquareCorner::NorthWest => SQUARE_NORTH | SQUARE_WEST,
            SquareCorner::NorthEast => SQUARE_NORTH | SQUARE_EAST,
            SquareCorner::SouthEast => SQUARE_SOUTH | SQUARE_EAST,
            SquareCorner::SouthWest => SQUARE_SOUTH | SQUARE_WEST,
        }
    }

    fn opposite(self) -> SquareCorner {
        match self {
            SquareCorner::NorthWest => SquareCorner::SouthEast,
            SquareCorner::NorthEast => SquareCorner::SouthWest,
            SquareCorner::SouthEast => SquareCorner::NorthWest,
            SquareCorner::SouthWest => SquareCorner::NorthEast,
        }
    }

    /// An inner corner here and the outline along the two far sides: the cell is the bend
    /// of an L, drawn by `form` as a quarter around this corner.
    fn quarter_mask(self) -> u16 {
        self.inner_bit() | self.opposite().outer_mask()
    }
}

/// A point inside a square cell, with the linear terms every formula is made of.
struct SquareCell {
    /// 2x − 1, 1 − 2x, 2z − 1, 1 − 2z: from 0 in the middle to 1 on the east, west, north
    /// and south sides.
    east: f64,
    west: f64,
    north: f64,
    south: f64,
    /// 2x, 2 − 2x, 2z, 2 − 2z: twice the distances to the west, east, south and north sides.
    from_west: f64,
    from_east: f64,
    from_south: f64,
    from_north: f64,
}

impl SquareCell {
    fn new(x: f64, z: f64) -> SquareCell {
        SquareCell {
            east: 2.0 * x - 1.0,
            west: 1.0 - 2.0 * x,
            north: 2.0 * z - 1.0,
            south: 1.0 - 2.0 * z,
            from_west: 2.0 * x,
            from_east: 2.0 - 2.0 * x,
            from_south: 2.0 * z,
            from_north: 2.0 - 2.0 * z,
        }
    }

    /// Twice the distances to `corner` along x and along z.
    fn reach(&self, corner: SquareCorner) -> (f64, f64) {
        match corner {
            SquareCorner::NorthWest => (self.from_west, self.from_north),
            SquareCorner::NorthEast => (self.from_east, self.from_north),
            SquareCorner::SouthEast => (self.from_east, self.from_south),
            SquareCorner::SouthWest => (self.from_west, self.from_south),
        }
    }

    /// The side terms growing towards `corner` (along x, along z).
    fn towards(&self, corner: SquareCorner) -> (f64, f64) {
        match corner {
            SquareCorner::NorthWest => (self.west, self.north),
            SquareCorner::NorthEast => (self.east, self.north),
            SquareCorner::SouthEast => (self.east, self.south),
            SquareCorner::SouthWest => (self.west, self.south),
        }
    }

    /// The value of a quarter tile bending around `corner`, if `form` draws one.
    fn quarter(&self, corner: SquareCorner, form: u8) -> Option<f64> {
        match form {
            0 => {
                let (near_x, near_z) = self.towards(corner);
                let (far_x, far_z) = self.towards(corner.opposite());
                Some(max(max(far_x, far_z), min(near_x, near_z)))
            }
            1 => {
                let across = match corner {
                    SquareCorner::NorthWest => self.from_west - self.from_south,
                    SquareCorner::NorthEast => self.from_north - self.from_west,
                    SquareCorner::SouthEast => self.from_south - self.from_west,
                    SquareCorner::SouthWest => self.from_west - self.from_north,
                };
                Some(min((across + 1.0).abs(), 1.0))
            }
            2 => {
                let (dx, dz) = self.reach(corner);
                Some(min(((dx * dx + dz * dz).sqrt() - 1.0).abs(), 1.0))
            }
            _ => None,
        }
    }

    /// The value near an inner corner of a tile at `corner`.
    fn inner_corner(&self, corner: SquareCorner, interior: u8) -> f64 {
        let (dx, dz) = self.reach(corner);
        match interior {
            1 => 1.0 - (dx + dz),
            2 => 1.0 - (dx * dx + dz * dz).sqrt(),
            _ => {
                let (near_x, near_z) = self.towards(corner);
                min(near_x, near_z)
            }
        }
    }

    /// The value near an outer corner of a tile at `corner`, if `exterior` changes it.
    fn outer_corner(&self, corner: SquareCorner, exterior: u8) -> Option<f64> {
        match exterior {
            1 => {
                let (dx, dz) = self.reach(corner);
                Some(min(2.0 - (dx + dz), 1.0))
            }
            2 => {
                let (ex, nz) = (self.east, self.north);
                let inside = match corner {
                    SquareCorner::NorthWest => ex <= 0.0 && nz >= 0.0,
                    SquareCorner::NorthEast => ex >= 0.0 && nz >= 0.0,
                    SquareCorner::SouthEast => ex >= 0.0 && nz <= 0.0,
                    SquareCorner::SouthWest => ex <= 0.0 && nz <= 0.0,
                };
                inside.then(|| min((ex * ex + nz * nz).sqrt(), 1.0))
            }
            _ => None,
        }
    }
}

// The side bits of a triangle cell's code. The cell, once folded, has its base on z = 0 from
// (0, 0) to (1, 0) and its apex at (1/2, √3/2).
const TRIANGLE_WEST_SIDE: u16 = 0x01;
const TRIANGLE_EAST_SIDE: u16 = 0x02;
const TRIANGLE_BASE: u16 = 0x04;

/// A point folded into the triangle cell it lies in, with the cell's lattice coordinates.
struct TriangleCell {
    x: f64,
    z: f64,
    column: i64,
    row: i64,
}

impl TriangleCell {
    /// Rows of height √3/2, each cut into triangles pointing alternately up and down; the
    /// point is mirrored into the upward triangle standing on [0, 1], and the cell counted
    /// in half steps along the row.
    fn locate(x: f64, z: f64) -> TriangleCell {
        let column = grid_index(x);
        let row = grid_index(z / SQRT3);
        let mut x = x - column as f64;
        let mut z = z - SQRT3 * row as f64;
        let mut column = column.wrapping_mul(2);
        let mut row = row.wrapping_mul(2);
        if z > SQRT3_2 {
            z -= SQRT3_2;
            if x > 0.5 {
                x -= 0.5;
                column = column.wrapping_add(1);
            } else {
                x += 0.5;
                column = column.wrapping_sub(1);
            }
            row = row.wrapping_add(1);
        }
        if x == 0.0 || z / x > SQRT3 {
            z = SQRT3_2 - z;
            x = 0.5 - x;
            column = column.wrapping_sub(1);
        }
        if x == 1.0 || z / (1.0 - x) > SQRT3 {
            z = SQRT3_2 - z;
            x = 1.5 - x;
            column = column.wrapping_add(1);
        }
        TriangleCell { x, z, column, row }
    }
}

/// A vertex of the folded triangle cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Vertex {
    Apex,
    West,
    East,
}

impl Vertex {
    const ALL: [Vertex; 3] = [Vertex::Apex, Vertex::West, Vertex::East];
    /// The order in which POV-Ray tries the cut outer corners (the last that applies wins).
    const OUTER_ORDER: [Vertex; 3] = [Vertex::Apex, Vertex::East, Vertex::West];

    fn position(self) -> (f64, f64) {
        match self {
            Vertex::Apex => (0.5, SQRT3_2),
            Vertex::West => (0.0, 0.0),
            Vertex::East => (1.0, 0.0),
        }
    }

    /// The sides meeting here, as indices into `[west side, east side, base]`.
    fn sides(self) -> [usize; 2] {
        match self {
            Vertex::Apex => [0, 1],
            Vertex::West => [0, 2],
            Vertex::East => [1, 2],
        }
    }

    /// The side bits of the two sides meeting here: with both on the outline, an outer
    /// corner of a tile.
    fn outer_mask(self) -> u16 {
        const BITS: [u16; 3] = [TRIANGLE_WEST_SIDE, TRIANGLE_EAST_SIDE, TRIANGLE_BASE];
        let [a, b] = self.sides();
        BITS[a] | BITS[b]
    }

    /// Whether the vertex is an inner corner of a tile: the two sides meeting here and the
    /// cell's "no inner corner" bit 0x80 are all clear, or the hexagon tables force it.
    fn is_inner(self, code: u16) -> bool {
        let forced = match self {
            Vertex::Apex => 0x4000,
            Vertex::West => 0x2000,
            Vertex::East => 0x1000,
        };
        code & (self.outer_mask() | 0x80) == 0 || code & forced != 0
    }

    /// The value near this vertex as an inner corner, if `interior` gives one there.
    fn inner_corner(self, x: f64, z: f64, zones: &Zones, interior: u8) -> Option<f64> {
        match interior {
            0 => Some(match self {
                Vertex::Apex => 1.0 - (SQRT3_2 - z) * 2.0 * SQRT3,
                Vertex::West => 1.0 - (SQRT3 * x + z).abs() * SQRT3,
                Vertex::East => 1.0 - (SQRT3 * (x - 1.0) - z).abs() * SQRT3,
            }),
            1 if zones.open(self) => {
                let [a1, a2] = zones.a;
                Some(match self {
                    Vertex::Apex => min(1.5 * a1 - 2.0, 1.5 * a2 - 2.0),
                    Vertex::West => min(1.0 - 1.5 * a1, 1.0 - x * 3.0),
                    Vertex::East => min(1.0 - 1.5 * a2, x * 3.0 - 2.0),
                })
            }
            2 => {
                let (cx, cz) = self.position();
                let (dx, dz) = (x - cx, z - cz);
                Some(1.0 - (dx * dx + dz * dz).sqrt() * 3.0)
            }
            _ => None,
        }
    }

    /// The cut (`exterior 1`) outer corner here, from the offsets (`dx`, `dz`) of the point
    /// to the cell's centre.
    fn cut_outer_corner(self, dx: f64, dz: f64) -> f64 {
        match self {
            Vertex::Apex => (dz * 2.0 * SQRT3).abs(),
            Vertex::East => (SQRT3 * dx - dz).abs() * SQRT3,
            Vertex::West => (SQRT3 * dx + dz).abs() * SQRT3,
        }
    }
}

/// The three parts of a triangle cell that its medians cut out, one around each vertex.
struct Zones {
    /// |√3 z + x| and |√3 z − x + 1|.
    a: [f64; 2],
    /// 1 − a[0], 1 − a[1] and 1 − 2x: zero on the medians from the east vertex, from the
    /// west vertex and from the apex, and positive on the side of the west vertex, of the
    /// east vertex and of the west vertex respectively.
    d: [f64; 3],
}

impl Zones {
    fn new(x: f64, z: f64) -> Zones {
        let a = [(SQRT3 * z + x).abs(), (SQRT3 * z - x + 1.0).abs()];
        Zones {
            a,
            d: [1.0 - a[0], 1.0 - a[1], 1.0 - x * 2.0],
        }
    }

    /// Strictly inside the zone of `vertex`.
    fn open(&self, vertex: Vertex) -> bool {
        let [d1, d2, d3] = self.d;
        match vertex {
            Vertex::Apex => d1 < 0.0 && d2 < 0.0,
            Vertex::West => d1 > 0.0 && d3 > 0.0,
            Vertex::East => d3 < 0.0 && d2 > 0.0,
        }
    }

    /// Inside the zone of `vertex` or on its border.
    fn closed(&self, vertex: Vertex) -> bool {
        let [d1, d2, d3] = self.d;
        match vertex {
            Vertex::Apex => d1 <= 0.0 && d2 <= 0.0,
            Vertex::West => d1 >= 0.0 && d3 >= 0.0,
            Vertex::East => d2 >= 0.0 && d3 <= 0.0,
        }
    }
}

/// A triangle cell that `form` draws as a piece of a bend: when the code has all of `mask`
/// and the point is strictly inside the zone of `zone`, the value is `sign · d[line] · 2`
/// (`form 1`) or the distance to the circle of radius 1/√3 around `centre` (`form 2`).
struct TriangleQuarter {
    mask: u16,
    zone: Vertex,
    line: usize,
    sign: f64,
    centre: Vertex,
}

impl TriangleQuarter {
    const fn new(mask: u16, zone: Vertex, line: usize, sign: f64, centre: Vertex) -> Self {
        TriangleQuarter {
            mask,
            zone,
            line,
            sign,
            centre,
        }
    }
}

/// In the order POV-Ray tries them (the first that applies wins).
#[rustfmt::skip]
const TRIANGLE_QUARTERS: [TriangleQuarter; 6] = [
    TriangleQuarter::new(0x120, Vertex::Apex, 0, -1.0, Vertex::West),
    TriangleQuarter::new(0x140, Vertex::West, 0,  1.0, Vertex::Apex),
    TriangleQuarter::new(0x210, Vertex::Apex, 1, -1.0, Vertex::East),
    TriangleQuarter::new(0x240, Vertex::East, 1,  1.0, Vertex::Apex),
    TriangleQuarter::new(0x410, Vertex::West, 2,  1.0, Vertex::East),
    TriangleQuarter::new(0x420, Vertex::East, 2, -1.0, Vertex::West),
];

/// How a cell's integer coordinates pick its entry in a variant's table of codes.
///
/// One coordinate, `v` (the row, or the column when `swapped`), is reduced modulo `period`;
/// every `step` of those rows the other coordinate, `u`, is shifted by `shift` before being
/// reduced modulo `wrap`. The table is `wrap` × `bands` codes, `v` picking the band by its
/// remainder modulo `bands`: band after band of `wrap` codes, or (when `swapped`) groups of
/// `bands` codes, one per value of `u`.
#[derive(Clone, Copy, Debug)]
struct Layout {
    swapped: bool,
    period: i64,
    step: i64,
    shift: i64,
    wrap: i64,
    bands: i64,
}

impl Layout {
    /// A plain `columns` × `rows` block repeated over the plane.
    const fn grid(columns: i64, rows: i64) -> Layout {
        Layout::sheared(rows, 1, 0, columns, rows)
    }

    /// Rows (of period `period`) whose columns shift by `shift` every `step` rows.
    const fn sheared(period: i64, step: i64, shift: i64, wrap: i64, bands: i64) -> Layout {
        Layout {
            swapped: false,
            period,
            step,
            shift,
            wrap,
            bands,
        }
    }

    /// Like [`Layout::sheared`] with the roles of columns and rows exchanged.
    const fn swapped(period: i64, step: i64, shift: i64, wrap: i64, bands: i64) -> Layout {
        Layout {
            swapped: true,
            ..Layout::sheared(period, step, shift, wrap, bands)
        }
    }

    const fn len(&self) -> usize {
        (self.wrap * self.bands) as usize
    }

    fn index(&self, column: i64, row: i64) -> usize {
        let (u, v) = if self.swapped {
            (row, column)
        } else {
            (column, row)
        };
        let v = v.rem_euclid(self.period);
        let u = u
            .wrapping_add(self.shift * (v / self.step))
            .rem_euclid(self.wrap);
        let band = v % self.bands;
        let index = if self.swapped {
            u * self.bands + band
        } else {
            u + band * self.wrap
        };
        index as usize
    }
}

/// One `pattern` of a `number_of_tiles`: its codes and how they lie on the plane.
struct Variant {
    layout: Layout,
    codes: &'static [u16],
}

impl Variant {
    const fn new(layout: Layout, codes: &'static [u16]) -> Variant {
        assert!(codes.len() == layout.len());
        Variant { layout, codes }
    }

    fn code(&self, column: i64, row: i64) -> u16 {
        self.codes[self.layout.index(column, row)]
    }
}

/// The variants for `sides` (anything but 4 and 6 being triangles), by `number_of_tiles`.
fn variants_of(sides: u8) -> &'static [&'static [Variant]] {
    match sides {
        4 => &SQUARE_VARIANTS,
        6 => &HEXAGON_VARIANTS,
        _ => &TRIANGLE_VARIANTS,
    }
}

// The codes are POV-Ray 3.7.0's tables (only the entries its addressing can reach). Square
// codes: side bits 0x01 north, 0x02 east, 0x04 south, 0x08 west; inner corners 0x10 north-
// west, 0x20 north-east, 0x40 south-east, 0x80 south-west. Triangle codes: side bits 0x01,
// 0x02, 0x04 (west, east, base), 0x80 no inner corners, 0x10 ..= 0x400 the pieces of bends
// drawn by `form`, 0x1000 ..= 0x4000 inner corners at the east, west and apex vertices
// whatever the sides.

/// Square cells: the variants of each `number_of_tiles`, in `pattern` order (a band of
/// codes per line).
#[rustfmt::skip]
static SQUARE_VARIANTS: [&[Variant]; 6] = [
    // number_of_tiles 1
    &[
        Variant::new(Layout::grid(1, 1), &[0x0F]),
    ],
    // number_of_tiles 2
    &[
        Variant::new(Layout::grid(1, 2), &[0x0E, 0x0B]),
    ],
    // number_of_tiles 3
    &[
        Variant::new(Layout::grid(3, 2), &[
            0x0D, 0x05, 0x07,
            0x0D, 0x05, 0x07,
        ]),
        Variant::new(Layout::grid(3, 2), &[
            0x0E, 0x0D, 0x16,
            0x49, 0x07, 0x0B,
        ]),
    ],
    // number_of_tiles 4
    &[
        Variant::new(Layout::grid(4, 4), &[
            0x0D, 0x05, 0x05, 0x07,
            0x0D, 0x05, 0x05, 0x07,
            0x0D, 0x05, 0x05, 0x07,
            0x0D, 0x05, 0x05, 0x07,
        ]),
        Variant::new(Layout::grid(4, 4), &[
            0x0E, 0x0D, 0x05, 0x16,
            0x49, 0x05, 0x07, 0x0B,
            0x0E, 0x0D, 0x05, 0x16,
            0x49, 0x05, 0x07, 0x0B,
        ]),
        Variant::new(Layout::grid(4, 4), &[
            0x0D, 0x34, 0x07, 0x0B,
            0x07, 0x0B, 0x0D, 0x34,
            0x0D, 0x34, 0x07, 0x0B,
            0x07, 0x0B, 0x0D, 0x34,
        ]),
        Variant::new(Layout::grid(4, 4), &[
            0x0C, 0x06, 0x0C, 0x06,
            0x09, 0x03, 0x09, 0x03,
            0x0C, 0x06, 0x0C, 0x06,
            0x09, 0x03, 0x09, 0x03,
        ]),
        Variant::new(Layout::grid(4, 4), &[
            0x07, 0x2C, 0x07, 0x2C,
            0x0D, 0x83, 0x0D, 0x83,
            0x2C, 0x07, 0x2C, 0x07,
            0x83, 0x0D, 0x83, 0x0D,
        ]),
    ],
    // number_of_tiles 5
    &[
        Variant::new(Layout::grid(5, 2), &[
            0x0D, 0x05, 0x05, 0x05, 0x07,
            0x0D, 0x05, 0x05, 0x05, 0x07,
        ]),
        Variant::new(Layout::grid(5, 2), &[
            0x0E, 0x0D, 0x05, 0x05, 0x16,
            0x49, 0x05, 0x05, 0x07, 0x0B,
        ]),
        Variant::new(Layout::sheared(10, 2, 3, 5, 2), &[
            0x07, 0x0C, 0x06, 0x0C, 0x24,
            0x0D, 0x81, 0x03, 0x09, 0x03,
        ]),
        Variant::new(Layout::sheared(5, 1, 2, 5, 1), &[0x0D, 0x05, 0x34, 0x07, 0x0B]),
        Variant::new(Layout::sheared(5, 1, 2, 5, 1), &[0x0D, 0xF0, 0x07, 0x0B, 0x0E]),
        Variant::new(Layout::sheared(10, 1, 1, 10, 1), &[
            0x0E, 0x0A, 0x49, 0x05, 0x07, 0x0D, 0x05, 0x16, 0x0A, 0x0B,
        ]),
        Variant::new(Layout::sheared(10, 1, 1, 10, 1), &[
            0x0B, 0x0E, 0x49, 0x16, 0x49, 0x07, 0x0D, 0x16, 0x49, 0x16,
        ]),
        Variant::new(Layout::sheared(10, 1, 3, 10, 1), &[
            0x2C, 0x05, 0x16, 0x0B, 0x0E, 0x0B, 0x0E, 0x49, 0x05, 0x83,
        ]),
        Variant::new(Layout::sheared(10, 1, 1, 10, 1), &[
            0x0E, 0x49, 0x05, 0x16, 0x0B, 0x0E, 0x49, 0x05, 0x16, 0x0B,
        ]),
        Variant::new(Layout::sheared(10, 2, 3, 5, 2), &[
            0x0E, 0x0D, 0xC1, 0x16, 0x0B,
            0x49, 0x34, 0x07, 0x0B, 0x0E,
        ]),
        Variant::new(Layout::sheared(10, 2, 4, 5, 2), &[
            0x07, 0x2C, 0x05, 0x07, 0x2C,
            0x0D, 0x83, 0x0D, 0x05, 0x83,
        ]),
        Variant::new(Layout::sheared(10, 1, 8, 10, 1), &[
            0x0D, 0x34, 0x07, 0x0D, 0xC1, 0x07, 0x0A, 0x0B, 0x0E, 0x0A,
        ]),
    ],
    // number_of_tiles 6
    &[
        Variant::new(Layout::grid(6, 2), &[
            0x0D, 0x05, 0x05, 0x05, 0x05, 0x07,
            0x0D, 0x05, 0x05, 0x05, 0x05, 0x07,
        ]),
        Variant::new(Layout::grid(6, 2), &[
            0x2C, 0x05, 0x05, 0x05, 0x07, 0x0E,
            0x0B, 0x0D, 0x05, 0x05, 0x05, 0x83,
        ]),
        Variant::new(Layout::grid(6, 2), &[
            0x0D, 0x34, 0x05, 0x05, 0x07, 0x0E,
            0x07, 0x0B, 0x0D, 0x05, 0x05, 0xC1,
        ]),
        Variant::new(Layout::grid(6, 2), &[
            0x0D, 0x05, 0x34, 0x05, 0x07, 0x0E,
            0x05, 0x07, 0x0B, 0x0D, 0x05, 0xC1,
        ]),
        Variant::new(Layout::sheared(6, 1, 5, 6, 1), &[0x0D, 0x83, 0x2C, 0x05, 0x05, 0x07]),
        Variant::new(Layout::grid(6, 2), &[
            0x0C, 0x24, 0x05, 0x07, 0x0C, 0x06,
            0x09, 0x03, 0x0D, 0x05, 0x81, 0x03,
        ]),
        Variant::new(Layout::grid(6, 2), &[
            0x07, 0x0C, 0x06, 0x0D, 0x14, 0x24,
            0x0D, 0x81, 0x41, 0x07, 0x09, 0x03,
        ]),
        Variant::new(Layout::sheared(6, 1, 5, 6, 1), &[0x0D, 0x05, 0x83, 0x2C, 0x05, 0x07]),
        Variant::new(Layout::grid(6, 2), &[
            0x07, 0x0C, 0x24, 0x07, 0x0C, 0x24,
            0x0D, 0x81, 0x03, 0x0D, 0x81, 0x03,
        ]),
        Variant::new(Layout::grid(6, 2), &[
            0x0C, 0x04, 0x06, 0x0C, 0x04, 0x06,
            0x09, 0x01, 0x03, 0x09, 0x01, 0x03,
        ]),
        Variant::new(Layout::grid(4, 3), &[
            0x0E, 0x0D, 0x14, 0x06,
            0x48, 0x06, 0x09, 0x12,
            0x09, 0x41, 0x07, 0x0B,
        ]),
        Variant::new(Layout::sheared(6, 1, 1, 6, 1), &[0x0D, 0x05, 0x16, 0x49, 0x16, 0x0B]),
        Variant::new(Layout::grid(4, 3), &[
            0x0D, 0x34, 0x05, 0x16,
            0x0E, 0x0B, 0x0E, 0x0B,
            0x49, 0x05, 0xC1, 0x07,
        ]),
        Variant::new(Layout::grid(3, 4), &[
            0x0D, 0x34, 0x07,
            0x16, 0x0A, 0x0D,
            0x0A, 0x49, 0x07,
            0xC1, 0x07, 0x0D,
        ]),
        Variant::new(Layout::sheared(6, 2, 2, 3, 2), &[
            0x0D, 0x14, 0x82,
            0x0E, 0x09, 0x03,
        ]),
        Variant::new(Layout::swapped(6, 2, 1, 3, 2), &[
            0x0E, 0x0D,
            0xD0, 0x06,
            0x09, 0x03,
        ]),
        Variant::new(Layout::sheared(12, 2, 1, 6, 2), &[
            0x0D, 0xF0, 0x05, 0x07, 0x0E, 0x0B,
            0x0E, 0x0B, 0x0D, 0x05, 0xF0, 0x07,
        ]),
        Variant::new(Layout::sheared(12, 2, 1, 6, 2), &[
            0x0E, 0x0B, 0x0D, 0x05, 0x05, 0x92,
            0x68, 0x05, 0x05, 0x07, 0x0E, 0x0B,
        ]),
        Variant::new(Layout::sheared(6, 1, 1, 6, 1), &[0x0E, 0x49, 0x05, 0x16, 0x0A, 0x0B]),
        Variant::new(Layout::sheared(6, 1, 5, 6, 1), &[0x0B, 0x2C, 0x05, 0x05, 0x83, 0x0E]),
        Variant::new(Layout::sheared(6, 1, 5, 6, 1), &[0x0B, 0x0A, 0x2C, 0x05, 0x05, 0x07]),
        Variant::new(Layout::grid(4, 3), &[
            0x2C, 0x05, 0x05, 0x16,
            0x0B, 0x0E, 0x0E, 0x0B,
            0x05, 0x83, 0x49, 0x05,
        ]),
        Variant::new(Layout::grid(4, 3), &[
            0x0A, 0x0D, 0xC1, 0x16,
            0x49, 0x34, 0x07, 0x0A,
            0x0E, 0x0B, 0x0E, 0x0B,
        ]),
        Variant::new(Layout::sheared(12, 2, 4, 6, 2), &[
            0x0D, 0x16, 0x0D, 0x05, 0x92, 0x0B,
            0x0E, 0x68, 0x05, 0x07, 0x49, 0x07,
        ]),
        Variant::new(Layout::grid(4, 3), &[
            0x0D, 0x16, 0x0D, 0x16,
            0x16, 0x49, 0x16, 0x49,
            0x49, 0x07, 0x49, 0x07,
        ]),
        Variant::new(Layout::grid(4, 3), &[
            0x0C, 0x06, 0x0C, 0x06,
            0x09, 0x12, 0x09, 0x12,
            0x07, 0x49, 0x07, 0x49,
        ]),
        Variant::new(Layout::grid(4, 3), &[
            0x2C, 0x07, 0x2C, 0x07,
            0x92, 0x0D, 0x92, 0x0D,
            0x49, 0x07, 0x49, 0x07,
        ]),
        Variant::new(Layout::sheared(6, 1, 1, 6, 1), &[0x0E, 0x49, 0x05, 0x16, 0x49, 0x07]),
        Variant::new(Layout::sheared(12, 2, 4, 6, 2), &[
            0x0D, 0x16, 0x0B, 0x0E, 0x49, 0x07,
            0x16, 0x49, 0x05, 0x83, 0x2C, 0x05,
        ]),
        Variant::new(Layout::sheared(4, 2, 3, 6, 2), &[
            0x07, 0x0E, 0x49, 0x34, 0x07, 0x49,
            0x0D, 0xC1, 0x16, 0x0B, 0x0D, 0x16,
        ]),
        Variant::new(Layout::sheared(4, 2, 3, 6, 2), &[
            0x2C, 0x05, 0xC1, 0x07, 0x0E, 0x0B,
            0x0B, 0x0D, 0x34, 0x05, 0x83, 0x0E,
        ]),
        Variant::new(Layout::sheared(3, 1, 4, 6, 1), &[0x0E, 0x0B, 0x0D, 0x34, 0xC1, 0x07]),
        Variant::new(Layout::grid(3, 4), &[
            0x0D, 0x05, 0x16,
            0x2C, 0x07, 0x0A,
            0x0A, 0x0D, 0x83,
            0x49, 0x05, 0x07,
        ]),
        Variant::new(Layout::sheared(12, 1, 7, 12, 1), &[
            0x2C, 0xC1, 0x05, 0x07, 0x0E, 0x0B, 0x0E, 0x0B, 0x0D, 0x05, 0x34, 0x83,
        ]),
        Variant::new(Layout::sheared(6, 3, 2, 4, 3), &[
            0x0A, 0x0D, 0x05, 0x92,
            0x68, 0x05, 0x07, 0x0A,
            0x0B, 0x0E, 0x0E, 0x0B,
        ]),
    ],
];

/// Triangle cells: the variants of each `number_of_tiles`, in `pattern` order.
#[rustfmt::skip]
static TRIANGLE_VARIANTS: [&[Variant]; 6] = [
    // number_of_tiles 1
    &[
        Variant::new(Layout::grid(1, 1), &[0x0007]),
    ],
    // number_of_tiles 2
    &[
        Variant::new(Layout::grid(1, 1), &[0x0166]),
    ],
    // number_of_tiles 3
    &[
        Variant::new(Layout::sheared(2, 1, 3, 6, 1), &[
            0x0215, 0x0344, 0x0126, 0x0126, 0x0344, 0x0215,
        ]),
    ],
    // number_of_tiles 4
    &[
        Variant::new(Layout::sheared(4, 1, 1, 4, 2), &[
            0x0126, 0x0126, 0x0144, 0x0144,
            0x0126, 0x0126, 0x0144, 0x0144,
        ]),
        Variant::new(Layout::sheared(4, 1, 1, 4, 2), &[
            0x0611, 0x0344, 0x0126, 0x0423,
            0x0611, 0x0344, 0x0126, 0x0423,
        ]),
        Variant::new(Layout::sheared(4, 1, 1, 4, 2), &[
            0x0005, 0x0000, 0x0006, 0x0003,
            0x0000, 0x0005, 0x0003, 0x0006,
        ]),
    ],
    // number_of_tiles 5
    &[
        Variant::new(Layout::sheared(2, 1, 5, 10, 1), &[
            0x0215, 0x0244, 0x0004, 0x0144, 0x0126, 0x0126, 0x0144, 0x0004, 0x0244, 0x0215,
        ]),
        Variant::new(Layout::sheared(2, 1, 5, 10, 1), &[
            0x0215, 0x0244, 0x0244, 0x0611, 0x0611, 0x0244, 0x0244, 0x0215, 0x0423, 0x0423,
        ]),
        Variant::new(Layout::sheared(2, 1, 5, 10, 1), &[
            0x0146, 0x0126, 0x0344, 0x0611, 0x0611, 0x0344, 0x0126, 0x0146, 0x0522, 0x0522,
        ]),
        Variant::new(Layout::sheared(10, 1, 3, 10, 1), &[
            0x0005, 0x0000, 0x0244, 0x0215, 0x0003, 0x0003, 0x0215, 0x0244, 0x0000, 0x0005,
        ]),
    ],
    // number_of_tiles 6
    &[
        Variant::new(Layout::sheared(6, 1, 5, 6, 1), &[
            0x0215, 0x0244, 0x0004, 0x0004, 0x0244, 0x0215,
        ]),
        Variant::new(Layout::sheared(6, 1, 5, 6, 1), &[
            0x0413, 0x0522, 0x0144, 0x0004, 0x0244, 0x0215,
        ]),
        Variant::new(Layout::sheared(2, 1, 3, 6, 1), &[
            0x0003, 0x0126, 0x0144, 0x0000, 0x0244, 0x0215,
        ]),
        Variant::new(Layout::sheared(6, 2, 14, 6, 2), &[
            0x0215, 0x0244, 0x0004, 0x0000, 0x0006, 0x0003,
            0x0004, 0x0244, 0x0215, 0x0003, 0x0006, 0x0000,
        ]),
        Variant::new(Layout::sheared(6, 2, 8, 6, 2), &[
            0x0005, 0x0000, 0x0244, 0x0215, 0x0245, 0x0211,
            0x0005, 0x0211, 0x0245, 0x0215, 0x0244, 0x0000,
        ]),
        Variant::new(Layout::grid(6, 2), &[
            0x0245, 0x0211, 0x0215, 0x0244, 0x0244, 0x0211,
            0x0245, 0x0211, 0x0244, 0x0244, 0x0215, 0x0211,
        ]),
        Variant::new(Layout::sheared(12, 3, -1, 4, 3), &[
            0x0215, 0x0244, 0x0244, 0x0611,
            0x0522, 0x0146, 0x0146, 0x0522,
            0x0611, 0x0244, 0x0244, 0x0215,
        ]),
        Variant::new(Layout::sheared(12, 3, -1, 4, 3), &[
            0x0005, 0x0000, 0x0244, 0x0215,
            0x0146, 0x0122, 0x0122, 0x0146,
            0x0215, 0x0244, 0x0000, 0x0005,
        ]),
        Variant::new(Layout::sheared(6, 2, 8, 6, 2), &[
            0x0005, 0x0000, 0x0006, 0x0126, 0x0344, 0x0211,
            0x0005, 0x0211, 0x0344, 0x0126, 0x0006, 0x0000,
        ]),
        Variant::new(Layout::sheared(6, 1, 5, 6, 1), &[
            0x0215, 0x0344, 0x0122, 0x0122, 0x0344, 0x0215,
        ]),
        Variant::new(Layout::sheared(2, 1, 3, 6, 1), &[
            0x0005, 0x0000, 0x0006, 0x0006, 0x0000, 0x0005,
        ]),
        Variant::new(Layout::sheared(2, 1, 3, 6, 1), &[
            0x0691, 0x03C4, 0x05A2, 0x05A2, 0x03C4, 0x0691,
        ]),
    ],
];

/// Hexagons, as rings of six triangle cells: the variants of each `number_of_tiles`, in
/// `pattern` order.
#[rustfmt::skip]
static HEXAGON_VARIANTS: [&[Variant]; 5] = [
    // number_of_tiles 1
    &[
        Variant::new(Layout::sheared(2, 1, 3, 6, 1), &[
            0x0691, 0x03C4, 0x05A2, 0x05A2, 0x03C4, 0x0691,
        ]),
    ],
    // number_of_tiles 2
    &[
        Variant::new(Layout::grid(6, 2), &[
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0691,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
        ]),
    ],
    // number_of_tiles 3
    &[
        Variant::new(Layout::grid(6, 6), &[
            0x0691, 0x03C4, 0x05A2, 0x05A2, 0x03C4, 0x0691,
            0x05A2, 0x03C4, 0x0691, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0691, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(18, 6, 2, 6, 6), &[
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0691,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0691, 0x02C4, 0x4080, 0x1080, 0x1080, 0x0491,
            0x05A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x05A2,
            0x0491, 0x1080, 0x1080, 0x4080, 0x02C4, 0x0691,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x01C4, 0x05A2,
        ]),
        Variant::new(Layout::grid(18, 2), &[
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x05A2,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x00C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x00C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x05A2,
        ]),
    ],
    // number_of_tiles 4
    &[
        Variant::new(Layout::grid(6, 8), &[
            0x0691, 0x03C4, 0x05A2, 0x05A2, 0x03C4, 0x0691,
            0x05A2, 0x03C4, 0x0691, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0691, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(12, 6, 2, 8, 6), &[
            0x0691, 0x02C4, 0x4080, 0x1080, 0x0080, 0x2080,
            0x4080, 0x02C4, 0x0691, 0x0291, 0x03C4, 0x01A2,
            0x4080, 0x01C4, 0x05A2, 0x01A2, 0x03C4, 0x0291,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x0080, 0x1080,
            0x0691, 0x02C4, 0x4080, 0x1080, 0x0080, 0x2080,
            0x4080, 0x02C4, 0x0691, 0x0291, 0x03C4, 0x01A2,
            0x4080, 0x01C4, 0x05A2, 0x01A2, 0x03C4, 0x0291,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x0080, 0x1080,
        ]),
        Variant::new(Layout::grid(12, 2), &[
            0x0691, 0x02C4, 0x5080, 0x5080, 0x00C4, 0x6080,
            0x6080, 0x00C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x05A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x01A2,
            0x01A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(24, 6, -2, 8, 6), &[
            0x0691, 0x03C4, 0x05A2, 0x04A2, 0x3080, 0x0491,
            0x01A2, 0x03C4, 0x0691, 0x0691, 0x03C4, 0x05A2,
            0x6080, 0x01C4, 0x05A2, 0x01A2, 0x03C4, 0x0691,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x0491, 0x3080, 0x00A2, 0x05A2, 0x01C4, 0x6080,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x00A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
        ]),
        Variant::new(Layout::swapped(24, 6, -2, 8, 6), &[
            0x0691, 0x03C4, 0x01A2, 0x05A2, 0x01C4, 0x6080,
            0x5080, 0x02C4, 0x0691, 0x0491, 0x3080, 0x00A2,
            0x0291, 0x03C4, 0x05A2, 0x04A2, 0x3080, 0x0091,
            0x05A2, 0x03C4, 0x0291, 0x0691, 0x02C4, 0x5080,
            0x0691, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x01A2, 0x03C4, 0x0691, 0x0091, 0x3080, 0x04A2,
            0x6080, 0x01C4, 0x05A2, 0x00A2, 0x3080, 0x0491,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(24, 6, -2, 8, 6), &[
            0x0691, 0x03C4, 0x05A2, 0x00A2, 0x3080, 0x0491,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0691, 0x02C4, 0x4080, 0x1080, 0x1080, 0x0491,
            0x05A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x05A2,
            0x0491, 0x1080, 0x1080, 0x4080, 0x02C4, 0x0691,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x01C4, 0x05A2,
            0x0491, 0x3080, 0x00A2, 0x05A2, 0x03C4, 0x0691,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
        ]),
        Variant::new(Layout::grid(12, 4), &[
            0x0691, 0x03C4, 0x05A2, 0x01A2, 0x03C4, 0x0691,
            0x0091, 0x3080, 0x00A2, 0x05A2, 0x03C4, 0x0291,
            0x5080, 0x00C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x04A2, 0x3080, 0x0491, 0x0691, 0x02C4, 0x5080,
            0x0091, 0x3080, 0x00A2, 0x05A2, 0x03C4, 0x0291,
            0x0691, 0x03C4, 0x05A2, 0x01A2, 0x03C4, 0x0691,
            0x04A2, 0x3080, 0x0491, 0x0691, 0x02C4, 0x5080,
            0x5080, 0x00C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
        ]),
    ],
    // number_of_tiles 5
    &[
        Variant::new(Layout::grid(6, 10), &[
            0x0691, 0x03C4, 0x05A2, 0x05A2, 0x03C4, 0x0691,
            0x05A2, 0x03C4, 0x0691, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0691, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, -2, 10, 6), &[
            0x6080, 0x01C4, 0x05A2, 0x01A2, 0x03C4, 0x0691,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x0491, 0x3080, 0x00A2, 0x05A2, 0x01C4, 0x6080,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x00A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0691, 0x03C4, 0x05A2, 0x04A2, 0x3080, 0x0491,
            0x01A2, 0x03C4, 0x0691, 0x0691, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::grid(6, 10), &[
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0691,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0691, 0x02C4, 0x4080, 0x1080, 0x1080, 0x0491,
            0x05A2, 0x03C4, 0x0691, 0x0091, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0091, 0x0691, 0x03C4, 0x05A2,
            0x0491, 0x1080, 0x1080, 0x4080, 0x02C4, 0x0691,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x01C4, 0x05A2,
        ]),
        Variant::new(Layout::grid(6, 10), &[
            0x0691, 0x03C4, 0x05A2, 0x00A2, 0x3080, 0x0491,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0691, 0x02C4, 0x4080, 0x1080, 0x1080, 0x0491,
            0x05A2, 0x03C4, 0x0691, 0x0091, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0091, 0x0691, 0x03C4, 0x05A2,
            0x0491, 0x1080, 0x1080, 0x4080, 0x02C4, 0x0691,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x01C4, 0x05A2,
            0x0491, 0x3080, 0x00A2, 0x05A2, 0x03C4, 0x0691,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
        ]),
        Variant::new(Layout::swapped(30, 6, -2, 10, 6), &[
            0x6080, 0x01C4, 0x05A2, 0x00A2, 0x3080, 0x0491,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x0491, 0x3080, 0x00A2, 0x05A2, 0x01C4, 0x6080,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x00A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0691, 0x03C4, 0x05A2, 0x04A2, 0x3080, 0x0491,
            0x05A2, 0x03C4, 0x0691, 0x0691, 0x03C4, 0x05A2,
            0x0491, 0x3080, 0x04A2, 0x05A2, 0x03C4, 0x0691,
            0x00A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
        ]),
        Variant::new(Layout::grid(6, 10), &[
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0691,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0491, 0x1080, 0x0080, 0x0080, 0x1080, 0x0491,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x01C4, 0x05A2,
            0x0491, 0x3080, 0x00A2, 0x05A2, 0x03C4, 0x0691,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0691, 0x03C4, 0x05A2, 0x00A2, 0x3080, 0x0491,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0491, 0x1080, 0x0080, 0x0080, 0x1080, 0x0491,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x01C4, 0x05A2,
        ]),
        Variant::new(Layout::grid(6, 10), &[
            0x0691, 0x02C4, 0x4080, 0x1080, 0x1080, 0x0491,
            0x05A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x05A2,
            0x0491, 0x1080, 0x1080, 0x4080, 0x02C4, 0x0691,
            0x04A2, 0x2080, 0x0080, 0x0080, 0x2080, 0x04A2,
            0x0491, 0x1080, 0x0080, 0x0080, 0x1080, 0x0491,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x01C4, 0x05A2,
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0691,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0491, 0x1080, 0x0080, 0x0080, 0x1080, 0x0491,
            0x04A2, 0x2080, 0x0080, 0x0080, 0x2080, 0x04A2,
        ]),
        Variant::new(Layout::swapped(60, 3, -7, 20, 3), &[
            0x6080, 0x01C4, 0x05A2,
            0x05A2, 0x01C4, 0x4080,
            0x0691, 0x02C4, 0x4080,
            0x4080, 0x02C4, 0x0691,
            0x4080, 0x01C4, 0x05A2,
            0x05A2, 0x01C4, 0x6080,
            0x0691, 0x03C4, 0x01A2,
            0x05A2, 0x01C4, 0x6080,
            0x0491, 0x3080, 0x00A2,
            0x04A2, 0x3080, 0x0091,
            0x0491, 0x1080, 0x1080,
            0x04A2, 0x2080, 0x2080,
            0x0691, 0x03C4, 0x01A2,
            0x01A2, 0x03C4, 0x0691,
            0x2080, 0x2080, 0x04A2,
            0x1080, 0x1080, 0x0491,
            0x0091, 0x3080, 0x04A2,
            0x00A2, 0x3080, 0x0491,
            0x6080, 0x01C4, 0x05A2,
            0x01A2, 0x03C4, 0x0691,
        ]),
        Variant::new(Layout::swapped(30, 6, 2, 10, 6), &[
            0x6080, 0x00C4, 0x5080, 0x5080, 0x02C4, 0x0291,
            0x05A2, 0x03C4, 0x0291, 0x0291, 0x02C4, 0x5080,
            0x0691, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x5080, 0x02C4, 0x0691, 0x0091, 0x3080, 0x04A2,
            0x0091, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0691, 0x03C4, 0x05A2, 0x00A2, 0x3080, 0x0491,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x0691, 0x03C4, 0x01A2, 0x05A2, 0x01C4, 0x6080,
            0x01A2, 0x03C4, 0x0291, 0x0691, 0x03C4, 0x01A2,
        ]),
        Variant::new(Layout::swapped(30, 6, -2, 10, 6), &[
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0691,
            0x5080, 0x00C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x0291, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0291,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x00C4, 0x5080,
            0x0491, 0x3080, 0x00A2, 0x05A2, 0x03C4, 0x0691,
            0x06A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0691, 0x03C4, 0x05A2, 0x00A2, 0x3080, 0x0491,
            0x5080, 0x00C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x0291, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0291,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x00C4, 0x5080,
        ]),
        Variant::new(Layout::swapped(30, 6, 2, 10, 6), &[
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0691,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0491, 0x1080, 0x0080, 0x0080, 0x1080, 0x0091,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x00C4, 0x5080,
            0x0691, 0x03C4, 0x01A2, 0x05A2, 0x03C4, 0x0291,
            0x5080, 0x02C4, 0x0691, 0x0691, 0x02C4, 0x5080,
            0x0291, 0x03C4, 0x05A2, 0x01A2, 0x03C4, 0x0691,
            0x5080, 0x00C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0091, 0x1080, 0x0080, 0x0080, 0x1080, 0x0491,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x01C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, -6, 10, 6), &[
            0x0291, 0x03C4, 0x05A2, 0x01A2, 0x03C4, 0x0691,
            0x4080, 0x00C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x4080, 0x00C4, 0x4080, 0x1080, 0x1080, 0x0491,
            0x05A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x05A2,
            0x0491, 0x1080, 0x1080, 0x4080, 0x00C4, 0x4080,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x00C4, 0x4080,
            0x0691, 0x03C4, 0x01A2, 0x05A2, 0x03C4, 0x0291,
            0x01A2, 0x03C4, 0x0691, 0x0491, 0x1080, 0x1080,
            0x2080, 0x2080, 0x04A2, 0x04A2, 0x2080, 0x2080,
            0x1080, 0x1080, 0x0491, 0x0691, 0x03C4, 0x01A2,
        ]),
        Variant::new(Layout::swapped(30, 6, 6, 10, 6), &[
            0x0691, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x5080, 0x02C4, 0x0691, 0x0091, 0x3080, 0x04A2,
            0x0291, 0x03C4, 0x05A2, 0x00A2, 0x3080, 0x0491,
            0x5080, 0x00C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x0291, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0291,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x00C4, 0x5080,
            0x0491, 0x3080, 0x00A2, 0x05A2, 0x03C4, 0x0291,
            0x04A2, 0x3080, 0x0091, 0x0691, 0x02C4, 0x5080,
            0x0691, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x05A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, 2, 10, 6), &[
            0x0691, 0x03C4, 0x05A2, 0x05A2, 0x03C4, 0x0691,
            0x05A2, 0x03C4, 0x0691, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0091,
            0x04A2, 0x3080, 0x0091, 0x0691, 0x02C4, 0x5080,
            0x0691, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0291,
            0x5080, 0x02C4, 0x0291, 0x0291, 0x02C4, 0x5080,
            0x0291, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x5080, 0x02C4, 0x0691, 0x0091, 0x3080, 0x04A2,
            0x0091, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0691, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, 2, 10, 6), &[
            0x0291, 0x03C4, 0x05A2, 0x05A2, 0x03C4, 0x0691,
            0x05A2, 0x03C4, 0x0691, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0091,
            0x04A2, 0x3080, 0x0091, 0x0691, 0x02C4, 0x5080,
            0x0691, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0291,
            0x5080, 0x02C4, 0x0291, 0x0291, 0x02C4, 0x5080,
            0x0291, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x5080, 0x02C4, 0x0691, 0x0291, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, 2, 10, 6), &[
            0x0691, 0x02C4, 0x5080, 0x5080, 0x00C4, 0x4080,
            0x01A2, 0x03C4, 0x0691, 0x0291, 0x02C4, 0x4080,
            0x2080, 0x2080, 0x04A2, 0x05A2, 0x03C4, 0x0691,
            0x1080, 0x1080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0091, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0091,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x1080, 0x1080,
            0x0691, 0x03C4, 0x05A2, 0x04A2, 0x2080, 0x2080,
            0x4080, 0x02C4, 0x0291, 0x0691, 0x03C4, 0x01A2,
            0x4080, 0x00C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x05A2, 0x03C4, 0x0291, 0x0291, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, -6, 10, 6), &[
            0x4080, 0x01C4, 0x01A2, 0x01A2, 0x01C4, 0x4080,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x00C4, 0x4080,
            0x0691, 0x03C4, 0x01A2, 0x05A2, 0x03C4, 0x0691,
            0x01A2, 0x03C4, 0x0691, 0x0491, 0x3080, 0x04A2,
            0x2080, 0x2080, 0x04A2, 0x04A2, 0x3080, 0x0091,
            0x1080, 0x1080, 0x0491, 0x0491, 0x1080, 0x1080,
            0x0091, 0x3080, 0x04A2, 0x04A2, 0x2080, 0x2080,
            0x04A2, 0x3080, 0x0491, 0x0691, 0x03C4, 0x01A2,
            0x0691, 0x03C4, 0x05A2, 0x01A2, 0x03C4, 0x0691,
            0x4080, 0x00C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, 2, 10, 6), &[
            0x0291, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0291,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x00C4, 0x5080,
            0x0691, 0x03C4, 0x01A2, 0x05A2, 0x03C4, 0x0691,
            0x5080, 0x02C4, 0x0691, 0x0491, 0x3080, 0x04A2,
            0x0091, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0091,
            0x04A2, 0x3080, 0x0491, 0x0691, 0x02C4, 0x5080,
            0x0691, 0x03C4, 0x05A2, 0x01A2, 0x03C4, 0x0691,
            0x5080, 0x00C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, 6, 10, 6), &[
            0x0091, 0x3080, 0x04A2, 0x05A2, 0x03C4, 0x0691,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0691, 0x03C4, 0x05A2, 0x00A2, 0x3080, 0x0091,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x00C4, 0x5080,
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0691,
            0x5080, 0x00C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x0091, 0x3080, 0x00A2, 0x05A2, 0x03C4, 0x0691,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0691, 0x03C4, 0x05A2, 0x04A2, 0x3080, 0x0091,
            0x5080, 0x02C4, 0x0691, 0x0691, 0x02C4, 0x5080,
        ]),
        Variant::new(Layout::grid(6, 10), &[
            0x0691, 0x03C4, 0x01A2, 0x01A2, 0x03C4, 0x0691,
            0x05A2, 0x01C4, 0x4080, 0x2080, 0x2080, 0x04A2,
            0x0691, 0x02C4, 0x4080, 0x1080, 0x1080, 0x0091,
            0x5080, 0x02C4, 0x0691, 0x0291, 0x02C4, 0x5080,
            0x0091, 0x3080, 0x04A2, 0x05A2, 0x03C4, 0x0691,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0691, 0x03C4, 0x05A2, 0x04A2, 0x3080, 0x0091,
            0x5080, 0x02C4, 0x0291, 0x0691, 0x02C4, 0x5080,
            0x0091, 0x1080, 0x1080, 0x4080, 0x02C4, 0x0691,
            0x04A2, 0x2080, 0x2080, 0x4080, 0x01C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, 2, 10, 6), &[
            0x0291, 0x03C4, 0x05A2, 0x05A2, 0x03C4, 0x0691,
            0x05A2, 0x03C4, 0x0691, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0091,
            0x04A2, 0x3080, 0x0091, 0x0691, 0x02C4, 0x5080,
            0x0691, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x5080, 0x02C4, 0x0691, 0x0091, 0x3080, 0x04A2,
            0x0091, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0091,
            0x04A2, 0x3080, 0x0091, 0x0691, 0x02C4, 0x5080,
            0x0691, 0x02C4, 0x5080, 0x5080, 0x02C4, 0x0691,
            0x5080, 0x02C4, 0x0691, 0x0291, 0x03C4, 0x05A2,
        ]),
        Variant::new(Layout::swapped(30, 6, 2, 10, 6), &[
            0x0691, 0x03C4, 0x01A2, 0x05A2, 0x03C4, 0x0291,
            0x5080, 0x02C4, 0x0691, 0x0691, 0x02C4, 0x5080,
            0x0291, 0x03C4, 0x05A2, 0x01A2, 0x03C4, 0x0691,
            0x5080, 0x00C4, 0x6080, 0x6080, 0x01C4, 0x05A2,
            0x0091, 0x3080, 0x00A2, 0x05A2, 0x03C4, 0x0691,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0491, 0x3080, 0x04A2, 0x04A2, 0x3080, 0x0491,
            0x04A2, 0x3080, 0x0491, 0x0491, 0x3080, 0x04A2,
            0x0691, 0x03C4, 0x05A2, 0x00A2, 0x3080, 0x0091,
            0x05A2, 0x01C4, 0x6080, 0x6080, 0x00C4, 0x5080,
        ]),
    ],
];

#[cfg(test)]
mod tests {
    use super::*;

    fn pavement(sides: u8, tiles: u8, pattern: u8, ext: u8, int: u8, form: u8) -> Pavement {
        Pavement {
            sides,
            tiles,
            pattern,
            exterior: ext,
            interior: int,
            form,
        }
    }

    /// Values printed by POV-Ray 3.7.0 (through a `pigment` function with frequencies 1 and
    /// 65536, which gives them to about 1e-12).
    #[test]
    fn matches_pov_ray() {
        #[rustfmt::skip]
        let cases = [
            (Pavement::default(), -3.7573311571646983, -0.6706373199008411, 0.566428616986),
            (pavement(4, 6, 35, 2, 2, 2), 4.580647850995486, -4.087059011232649, 0.143412593342),
            (pavement(4, 5, 9, 1, 1, 1), -3.7573311571646983, -0.6706373199008411, 0.855936954131),
            (pavement(4, 3, 2, 0, 0, 0), -3.7573311571646983, -0.6706373199008411, 0.514662314330),
            (pavement(3, 6, 12, 1, 1, 1), -2.6737889677159234, 0.2359758016465836, 0.695155870864),
            (pavement(3, 4, 2, 2, 2, 2), 3.252065092537432, -2.013601448004072, 0.768416274184),
            (pavement(6, 5, 8, 0, 1, 2), 3.731899671198791, -2.8361956970995528, 0.365105396917),
            (pavement(6, 4, 7, 0, 0, 1), 4.580647850995486, -4.087059011232649, 0.157987721974),
            // on a lattice vertex
            (pavement(3, 6, 12, 0, 0, 0), 0.0, 3.4641016151377544, 1.0),
        ];
        for (p, x, z, expected) in cases {
            let value = p.value([x, 0.2, z]);
            assert!(
                (value - expected).abs() < 1e-9,
                "{p:?} at ({x}, {z}): {value} vs {expected}"
            );
        }
    }

    #[test]
    fn parser_checks() {
        assert_eq!(
            pavement(4, 5, 1, 4, 7, 5).checked(),
            Ok(pavement(4, 5, 1, 1, 1, 1))
        );
        assert_eq!(
            pavement(6, 5, 22, 8, 5, 5).checked(),
            Ok(pavement(6, 5, 22, 2, 2, 2))
        );
        assert_eq!(
            pavement(5, 1, 1, 0, 0, 0).checked(),
            Err(PavementError::Sides)
        );
        assert_eq!(
            pavement(6, 6, 1, 0, 0, 0).checked(),
            Err(PavementError::Tiles(6))
        );
        assert_eq!(
            pavement(4, 5, 99, 0, 0, 0).checked(),
            Err(PavementError::Pattern(4))
        );
        assert_eq!(
            pavement(3, 3, 0, 0, 0, 0).checked(),
            Err(PavementError::Pattern(3))
        );
        assert_eq!(
            PavementError::Pattern(4).to_string(),
            "pattern value for pavement is out of range. max per tile:(1,1,2,5,12,35)"
        );
        assert_eq!(
            PavementError::Tiles(6).to_string(),
            "number_of_tiles of pavement must be between 1 and 5."
        );
        assert_eq!(max_pattern(6, 5), Some(22));
        assert_eq!(max_pattern(3, 6), Some(12));
        assert_eq!(max_pattern(4, 7), None);
    }

    #[test]
    fn keyword_values_become_bytes_like_pov_ray() {
        assert_eq!(parameter_byte(257.0), 1);
        assert_eq!(parameter_byte(-255.0), 1);
        assert_eq!(parameter_byte(1.9), 1);
        assert_eq!(parameter_byte(-1.0), 255);
        assert_eq!(parameter_byte(-0.5), 0);
        assert_eq!(parameter_byte(-2_147_483_647.0), 1);
        assert_eq!(parameter_byte(2_147_483_649.0), 0);
        assert_eq!(parameter_byte(4_294_967_297.0), 0);
    }

    #[test]
    fn values_stay_in_unit_interval() {
        for sides in [3, 4, 6] {
            for tiles in 1..=6 {
                let Some(max) = max_pattern(sides, tiles) else {
                    continue;
                };
                for pattern in 1..=max {
                    for options in 0..36u8 {
                        let p = pavement(
                            sides,
                            tiles,
                            pattern,
                            options % 3,
                            options / 3 % 3,
                            options / 9,
                        )
                        .checked()
                        .unwrap();
                        for i in 0..50 {
                            let t = f64::from(i);
                            let value = p.value([(t * 0.731).sin() * 7.0, 0.0, t * 0.377 - 9.0]);
                            assert!((0.0..=1.0).contains(&value), "{p:?}: {value}");
                        }
                    }
                }
            }
        }
    }
}
