//! Pictures streamed to a running tev (an HDR image viewer) over its IPC protocol, as
//! pbrt-v4's display server streams them: a TCP connection to tev's port (14158 by default)
//! carrying packets, each its length in bytes (a little-endian u32, counting itself) then its
//! type:
//!
//! - create image (4): grab focus (u8), the name (NUL-ended), width, height and the number
//!   of channels (i32 each), the channels' names (NUL-ended);
//! - update image (3): grab focus (u8), the name, one channel's name, x, y, width, height of
//!   a tile (i32 each), then the tile's values of that channel (f32, rows top first).
//!
//! Values are linear, as in an EXR. Tiles of 128 × 128 are sent only when they changed since
//! the last time, so a picture that gains a few blocks sends only those.

use std::io::Write;
use std::net::TcpStream;
use std::time::Duration;
use trace::Film;

const CREATE_IMAGE: u8 = 4;
const UPDATE_IMAGE: u8 = 3;
const TILE: u32 = 128;
const CHANNELS: [&str; 3] = ["R", "G", "B"];

/// A connection to tev showing one image, and what it was last sent.
pub struct Display {
    stream: TcpStream,
    name: String,
    sent: Option<Film>,
}

impl Display {
    /// Connects to tev at `address` (HOST:PORT); the image will be called `name`.
    pub fn connect(address: &str, name: &str) -> std::io::Result<Display> {
        let stream = TcpStream::connect(address)?;
        stream.set_write_timeout(Some(Duration::from_secs(3)))?;
        stream.set_nodelay(true)?;
        Ok(Display {
            stream,
            name: name.to_string(),
            sent: None,
        })
    }

    /// Shows `film`: creates the image when it is new or its size changed, then sends the
    /// tiles that differ from what tev holds.
    pub fn show(&mut self, film: &Film) -> std::io::Result<()> {
        let same_size = self
            .sent
            .as_ref()
            .is_some_and(|s| (s.width, s.height) == (film.width, film.height));
        if !same_size {
            self.stream
                .write_all(&create_image(&self.name, film.width, film.height))?;
            self.sent = None;
        }
        for ty in (0..film.height).step_by(TILE as usize) {
            for tx in (0..film.width).step_by(TILE as usize) {
                let (w, h) = (TILE.min(film.width - tx), TILE.min(film.height - ty));
                let changed = match &self.sent {
                    None => true,
                    Some(old) => {
                        (ty..ty + h).any(|y| (tx..tx + w).any(|x| old.get(x, y) != film.get(x, y)))
                    }
                };
                if changed {
                    for (c, channel) in CHANNELS.iter().enumerate() {
                        let values: Vec<f32> = (ty..ty + h)
                            .flat_map(|y| (tx..tx + w).map(move |x| (x, y)))
                            .map(|(x, y)| film.get(x, y)[c])
                            .collect();
                        self.stream.write_all(&update_image(
                            &self.name,
                            channel,
                            [tx, ty, w, h],
                            &values,
                        ))?;
                    }
                }
            }
        }
        self.stream.flush()?;
        self.sent = Some(film.clone());
        Ok(())
    }
}

/// A packet: its length first.
fn packet(body: Vec<u8>) -> Vec<u8> {
    let mut out = ((body.len() + 4) as u32).to_le_bytes().to_vec();
    out.extend(body);
    out
}

fn push_str(out: &mut Vec<u8>, s: &str) {
    out.extend(s.bytes().filter(|&b| b != 0));
    out.push(0);
}

/// The create-image packet of a `width` × `height` RGB image.
pub fn create_image(name: &str, width: u32, height: u32) -> Vec<u8> {
    let mut body = vec![CREATE_IMAGE, 1];
    push_str(&mut body, name);
    for v in [width as i32, height as i32, CHANNELS.len() as i32] {
        body.extend(v.to_le_bytes());
    }
    for channel in CHANNELS {
        push_str(&mut body, channel);
    }
    packet(body)
}

/// The update-image packet of one channel of the tile at `[x, y, width, height]`.
pub fn update_image(name: &str, channel: &str, tile: [u32; 4], values: &[f32]) -> Vec<u8> {
    let mut body = vec![UPDATE_IMAGE, 0];
    push_str(&mut body, name);
    push_str(&mut body, channel);
    for v in tile {
        body.extend((v as i32).to_le_bytes());
    }
    for v in values {
        body.extend(v.to_le_bytes());
    }
    packet(body)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packets_are_laid_out_as_tev_reads_them() {
        let p = create_image("a", 3, 2);
        assert_eq!(
            u32::from_le_bytes(p[..4].try_into().unwrap()) as usize,
            p.len()
        );
        assert_eq!(&p[4..8], &[4, 1, b'a', 0]);
        assert_eq!(&p[8..12], &3i32.to_le_bytes());
        assert_eq!(&p[12..16], &2i32.to_le_bytes());
        assert_eq!(&p[16..20], &3i32.to_le_bytes());
        assert_eq!(&p[20..], b"R\0G\0B\0");
        let u = update_image("a", "G", [1, 0, 2, 1], &[0.5, 2.0]);
        assert_eq!(
            u32::from_le_bytes(u[..4].try_into().unwrap()) as usize,
            u.len()
        );
        assert_eq!(&u[4..10], &[3, 0, b'a', 0, b'G', 0]);
        let ints: Vec<i32> = u[10..26]
            .chunks(4)
            .map(|c| i32::from_le_bytes(c.try_into().unwrap()))
            .collect();
        assert_eq!(ints, [1, 0, 2, 1]);
        assert_eq!(&u[26..30], &0.5f32.to_le_bytes());
        assert_eq!(&u[30..], &2.0f32.to_le_bytes());
    }
}
