//! RGBA8 images: PNG files, animated GIFs, and simple statistics for tests.

use std::io::Write;

/// An sRGB RGBA8 image, rows top to bottom.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// 4 bytes per pixel.
    pub rgba: Vec<u8>,
}

impl Image {
    /// The pixel at (x, y).
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 4] {
        let i = 4 * (y as usize * self.width as usize + x as usize);
        [self.rgba[i], self.rgba[i + 1], self.rgba[i + 2], self.rgba[i + 3]]
    }
    /// PNG bytes.
    pub fn to_png(&self) -> Vec<u8> {
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, self.width, self.height);
            enc.set_color(png::ColorType::Rgba);
            enc.set_depth(png::BitDepth::Eight);
            let mut w = enc.write_header().expect("PNG header into memory");
            w.write_image_data(&self.rgba).expect("PNG data into memory");
        }
        out
    }
    /// Writes a PNG file (through [`splinekit_scene::write_file`]: a failure leaves what was
    /// at `path` as it was).
    pub fn save_png(&self, path: &std::path::Path) -> std::io::Result<()> {
        splinekit_scene::write_file(path, &self.to_png())
    }
    /// Reads a PNG (8-bit RGBA or RGB).
    pub fn from_png(bytes: &[u8]) -> Result<Image, String> {
        let mut dec = png::Decoder::new(std::io::Cursor::new(bytes));
        dec.set_transformations(png::Transformations::EXPAND);
        let mut reader = dec.read_info().map_err(|e| e.to_string())?;
        let mut buf = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
        buf.truncate(info.buffer_size());
        let rgba = match info.color_type {
            png::ColorType::Rgba => buf,
            png::ColorType::Rgb => buf.chunks_exact(3).flat_map(|c| [c[0], c[1], c[2], 255]).collect(),
            other => return Err(format!("unsupported PNG colour type {other:?}")),
        };
        Ok(Image { width: info.width, height: info.height, rgba })
    }
    /// Mean absolute difference per channel (0–255) from another image of the same size.
    pub fn mean_difference(&self, other: &Image) -> Option<f64> {
        if (self.width, self.height) != (other.width, other.height) {
            return None;
        }
        let sum: u64 = self.rgba.iter().zip(&other.rgba).map(|(a, b)| a.abs_diff(*b) as u64).sum();
        Some(sum as f64 / self.rgba.len() as f64)
    }
    /// The fraction of pixels that differ from the colour at the top-left corner (the
    /// background) by more than 16 in some channel.
    pub fn coverage(&self) -> f64 {
        let bg = self.pixel(0, 0);
        let n = self.rgba.chunks_exact(4).filter(|p| (0..3).any(|k| p[k].abs_diff(bg[k]) > 16)).count();
        n as f64 / (self.width as f64 * self.height as f64)
    }
}

/// Writes frames as an endlessly looping GIF at `fps` frames per second (each frame
/// quantised to its own 256-colour palette).
pub fn write_gif<W: Write>(out: W, frames: &[Image], fps: f32) -> Result<(), String> {
    let first = frames.first().ok_or("no frames")?;
    let (w, h) = (
        u16::try_from(first.width).map_err(|_| "GIF images are at most 65535 wide")?,
        u16::try_from(first.height).map_err(|_| "GIF images are at most 65535 high")?,
    );
    let mut enc = gif::Encoder::new(out, w, h, &[]).map_err(|e| e.to_string())?;
    enc.set_repeat(gif::Repeat::Infinite).map_err(|e| e.to_string())?;
    let delay = (100.0 / fps.max(0.1)).round().clamp(2.0, 65535.0) as u16;
    for img in frames {
        if (img.width, img.height) != (first.width, first.height) {
            return Err("all frames must have one size".into());
        }
        let mut rgba = img.rgba.clone();
        let mut frame = gif::Frame::from_rgba_speed(w, h, &mut rgba, 10);
        frame.delay = delay;
        enc.write_frame(&frame).map_err(|e| e.to_string())?;
    }
    Ok(())
}
