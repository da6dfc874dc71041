//! Colours as integer channels: what shading blends.

use embedded_graphics_core::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, GrayColor, PixelColor,
    Rgb555, Rgb565, Rgb666, Rgb888, RgbColor,
};

/// A colour made of up to three integer channels, each blended in its own
/// range, in the order of the colour's raw bits, highest first: red,
/// green and blue for embedded-graphics' RGB colours, blue, green and red
/// for its BGR ones (`0..=31` / `0..=63` / `0..=31` for `Rgb565` and
/// `Bgr565`, `0..=31` each for `Rgb555` and `Bgr555`, `0..=63` for `Rgb666`
/// and `Bgr666`, `0..=255` for `Rgb888` and `Bgr888`), the luma for the
/// greys (`0..=3` for `Gray2`, `0..=15` for `Gray4`, `0..=255` for
/// `Gray8`), and `0..=1` for `BinaryColor`: every colour of the crate's
/// framebuffer formats. Blending treats the channels alike, so their
/// order changes no pixel; in the raw order, the channels of a shaded
/// pixel become its raw value by shifts alone.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{Bgr565, Gray4, Rgb565};
/// use embedded_raster::shade::ShadeColor;
///
/// let c = Rgb565::new(31, 40, 2);
/// assert_eq!(c.channels(), [31, 40, 2]);
/// assert_eq!(Rgb565::from_channels([31, 40, 2]), c);
/// assert_eq!(Rgb565::MAX, [31, 63, 31]);
/// // Blue first, as in its raw bits.
/// assert_eq!(Bgr565::new(31, 40, 2).channels(), [2, 40, 31]);
/// assert_eq!(Gray4::new(9).channels(), [9, 0, 0]);
/// assert_eq!(Gray4::MAX, [15, 0, 0]);
/// ```
pub trait ShadeColor: PixelColor {
    /// How many of the three channels are used (the rest are 0).
    const CHANNELS: usize;
    /// The largest value of each channel.
    const MAX: [u8; 3];
    /// The channels.
    fn channels(self) -> [u8; 3];
    /// The colour with these channels; each is at most its [`MAX`](Self::MAX).
    /// Above it, the built-in colours keep only the channel's low bits
    /// (the RGB, BGR and grey colours, as their `new` does) or read any
    /// non-zero value as on (`BinaryColor`); `Rgb888`, `Bgr888` and `Gray8`
    /// take every `u8`.
    fn from_channels(channels: [u8; 3]) -> Self;
}

/// [`ShadeColor`] for embedded-graphics' RGB and BGR colours: red, green
/// and blue, each up to the colour's own maximum, at the places `r`, `g`
/// and `b` of the channels (the order of the raw bits, highest first).
macro_rules! rgb_shade_color {
    ($r:literal, $g:literal, $b:literal: $($color:ident),* $(,)?) => {$(
        impl ShadeColor for $color {
            const CHANNELS: usize = 3;
            const MAX: [u8; 3] = {
                let mut max = [0; 3];
                max[$r] = Self::MAX_R;
                max[$g] = Self::MAX_G;
                max[$b] = Self::MAX_B;
                max
            };
            #[inline(always)]
            fn channels(self) -> [u8; 3] {
                let mut c = [0; 3];
                c[$r] = self.r();
                c[$g] = self.g();
                c[$b] = self.b();
                c
            }
            #[inline(always)]
            fn from_channels(c: [u8; 3]) -> Self {
                Self::new(c[$r], c[$g], c[$b])
            }
        }
    )*};
}

rgb_shade_color!(0, 1, 2: Rgb555, Rgb565, Rgb666, Rgb888);
rgb_shade_color!(2, 1, 0: Bgr555, Bgr565, Bgr666, Bgr888);

/// [`ShadeColor`] for embedded-graphics' greys: the luma, up to `max`
/// (`GrayColor` gives no constant maximum; a test checks each against the
/// colour's `WHITE`).
macro_rules! gray_shade_color {
    ($($color:ident = $max:literal),* $(,)?) => {$(
        impl ShadeColor for $color {
            const CHANNELS: usize = 1;
            const MAX: [u8; 3] = [$max, 0, 0];
            #[inline(always)]
            fn channels(self) -> [u8; 3] {
                [self.luma(), 0, 0]
            }
            #[inline(always)]
            fn from_channels([l, _, _]: [u8; 3]) -> Self {
                Self::new(l)
            }
        }
    )*};
}

gray_shade_color!(Gray2 = 3, Gray4 = 15, Gray8 = 255);

impl ShadeColor for BinaryColor {
    const CHANNELS: usize = 1;
    const MAX: [u8; 3] = [1, 0, 0];
    #[inline(always)]
    fn channels(self) -> [u8; 3] {
        [u8::from(self.is_on()), 0, 0]
    }
    #[inline(always)]
    fn from_channels([on, _, _]: [u8; 3]) -> Self {
        Self::from(on != 0)
    }
}

/// The rounded per-channel average of three colours: for each channel sum
/// `s`, `(2 s + 3) / 6` in integers, i.e. `s / 3` rounded to the nearest
/// integer (a third never ends in a half). For `BinaryColor` this is the
/// majority. Any colours: the sum is at most `3 * 255`, in `u16`, and the
/// result at most 255, so nothing overflows.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{BinaryColor, Rgb888};
/// use embedded_raster::shade::average_color;
///
/// let c = average_color([Rgb888::new(255, 0, 10), Rgb888::new(0, 0, 10), Rgb888::new(0, 1, 11)]);
/// assert_eq!(c, Rgb888::new(85, 0, 10)); // 255/3, 1/3 -> 0, 31/3 = 10.33 -> 10
/// let on = average_color([BinaryColor::On, BinaryColor::Off, BinaryColor::On]);
/// assert_eq!(on, BinaryColor::On);
/// ```
pub fn average_color<C: ShadeColor>(colors: [C; 3]) -> C {
    let [a, b, c] = colors.map(ShadeColor::channels);
    let mut out = [0u8; 3];
    for k in 0..3 {
        let s = u16::from(a[k]) + u16::from(b[k]) + u16::from(c[k]);
        // (2 s + 3) / 6 <= (2 * 765 + 3) / 6 = 255.
        out[k] = ((2 * s + 3) / 6) as u8;
    }
    C::from_channels(out)
}
