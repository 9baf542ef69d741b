//! `density_file df3 "file"`: a block of voxels read from a DF3 file (three big-endian 16-bit
//! sizes, then the voxels, x fastest, in 8, 16 or 32 bits as the file's length says), its
//! values 0 to 1 over the unit cube and 0 outside, as POV-Ray's `density_pattern` reads them:
//! the voxel the point falls in (`interpolate 0`), trilinear (1) or tricubic (2).

use glam::DVec3;

/// A DF3 file's voxels.
#[derive(Clone, PartialEq)]
pub struct DensityFile {
    /// The file as named in the scene.
    pub file: String,
    /// Voxels along x, y and z.
    pub size: [usize; 3],
    /// The voxels as stored, x fastest, then y, then z.
    pub voxels: Vec<u32>,
    /// The largest value of the file's voxel size (255, 65535 or 2³² − 1).
    pub max: f64,
    /// `interpolate`: 0 none, 1 trilinear, anything else tricubic (POV-Ray's `% 10`).
    pub interpolation: u32,
}

impl std::fmt::Debug for DensityFile {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("DensityFile")
            .field("file", &self.file)
            .field("size", &self.size)
            .field("interpolation", &self.interpolation)
            .finish()
    }
}

/// Reads a DF3 file's bytes.
pub fn parse(file: &str, bytes: &[u8]) -> Result<DensityFile, String> {
    if bytes.len() < 6 {
        return Err("too short for a DF3 header".to_string());
    }
    let size_at = |i: usize| usize::from(u16::from_be_bytes([bytes[i], bytes[i + 1]]));
    let size = [size_at(0), size_at(2), size_at(4)];
    let count = size[0] * size[1] * size[2];
    let data = &bytes[6..];
    let (voxels, max) = if count * 4 == data.len() {
        let v = data
            .chunks_exact(4)
            .map(|c| u32::from_be_bytes([c[0], c[1], c[2], c[3]]))
            .collect();
        (v, f64::from(u32::MAX))
    } else if count * 2 == data.len() {
        let v = data
            .chunks_exact(2)
            .map(|c| u32::from(u16::from_be_bytes([c[0], c[1]])))
            .collect();
        (v, f64::from(u16::MAX))
    } else if count == data.len() {
        (
            data.iter().map(|&b| u32::from(b)).collect(),
            f64::from(u8::MAX),
        )
    } else {
        return Err(format!(
            "{}×{}×{} voxels do not fill its {} bytes of data (1, 2 or 4 bytes each)",
            size[0],
            size[1],
            size[2],
            data.len()
        ));
    };
    Ok(DensityFile {
        file: file.to_string(),
        size,
        voxels,
        max,
        interpolation: 0,
    })
}

/// POV-Ray's cubic through four samples, at `t` between the middle two (single precision).
fn cubic(t: f32, a: f32, b: f32, c: f32, d: f32) -> f32 {
    let slope_b = (c - a) * 0.5;
    let slope_c = (d - b) * 0.5;
    let e = 2.0 * (b - c) + slope_b + slope_c;
    let f = -3.0 * (b - c) - 2.0 * slope_b - slope_c;
    ((e * t + f) * t + slope_b) * t + b
}

impl DensityFile {
    fn at(&self, x: usize, y: usize, z: usize) -> f64 {
        let [sx, sy, _] = self.size;
        f64::from(self.voxels[(z * sy + y) * sx + x]) / self.max
    }

    /// The value at `p`: 0 outside the unit cube, never below 0.
    pub fn value(&self, p: DVec3) -> f64 {
        let [sx, sy, sz] = self.size;
        if sx == 0
            || sy == 0
            || sz == 0
            || !(0.0..1.0).contains(&p.x)
            || !(0.0..1.0).contains(&p.y)
            || !(0.0..1.0).contains(&p.z)
        {
            return 0.0;
        }
        let scaled = p * DVec3::new(sx as f64, sy as f64, sz as f64);
        let (x1, y1, z1) = (scaled.x as usize, scaled.y as usize, scaled.z as usize);
        let density = match self.interpolation % 10 {
            0 => {
                if x1 >= sx || y1 >= sy || z1 >= sz {
                    0.0
                } else {
                    self.at(x1, y1, z1)
                }
            }
            1 => {
                let (x2, y2, z2) = ((x1 + 1) % sx, (y1 + 1) % sy, (z1 + 1) % sz);
                let f = scaled - scaled.floor();
                let (xi, yi) = (1.0 - f.x, 1.0 - f.y);
                let plane = |z: usize| {
                    (self.at(x1, y1, z) * xi + self.at(x2, y1, z) * f.x) * yi
                        + (self.at(x1, y2, z) * xi + self.at(x2, y2, z) * f.x) * f.y
                };
                plane(z1) * (1.0 - f.z) + plane(z2) * f.z
            }
            _ => {
                // Neighbours wrap around; one below the first wraps as POV-Ray's unsigned
                // arithmetic does (2⁶⁴ − 1 modulo the size).
                let wrap =
                    |i: usize, n: usize, d: isize| (i as u64).wrapping_add(d as u64) as usize % n;
                let f = scaled - scaled.floor();
                let (fx, fy, fz) = (f.x as f32, f.y as f32, f.z as f32);
                let mut across = [[0.0f32; 4]; 4];
                for (i, row) in across.iter_mut().enumerate() {
                    let ii = wrap(x1, sx, i as isize - 1);
                    for (j, v) in row.iter_mut().enumerate() {
                        let jj = wrap(y1, sy, j as isize - 1);
                        let sample = |d: isize| self.at(ii, jj, wrap(z1, sz, d)) as f32;
                        *v = cubic(fz, sample(-1), sample(0), sample(1), sample(2));
                    }
                }
                let mut along = [0.0f32; 4];
                for (i, v) in along.iter_mut().enumerate() {
                    *v = cubic(fy, across[i][0], across[i][1], across[i][2], across[i][3]);
                }
                f64::from(cubic(fx, along[0], along[1], along[2], along[3]))
            }
        };
        density.max(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_by_two() -> DensityFile {
        let mut bytes = vec![0, 2, 0, 2, 0, 2];
        bytes.extend([0u8, 255, 0, 255, 51, 51, 51, 51]);
        parse("t.df3", &bytes).unwrap()
    }

    #[test]
    fn voxels_and_interpolation() {
        let mut d = two_by_two();
        assert_eq!(d.value(DVec3::new(0.75, 0.25, 0.25)), 1.0);
        assert_eq!(d.value(DVec3::new(0.25, 0.25, 0.75)), 0.2);
        assert_eq!(d.value(DVec3::new(1.0, 0.5, 0.5)), 0.0);
        d.interpolation = 1;
        // Halfway between the first two voxels along x.
        assert!((d.value(DVec3::new(0.25, 0.0, 0.0)) - 0.5).abs() < 1e-12);
        assert!(parse("bad", &[0, 2, 0, 2, 0, 2, 1]).is_err());
    }
}
