//! The formats displays use (issue 14, item 7): `Bgr565Le`, `Bgr565Be`,
//! `Rgb666Bytes`, `Gray4Msb`, `Gray4Lsb`, `Gray2Msb` and `Gray2Lsb`, each
//! against an independent reference that starts from the same random bytes
//! and is drawn pixel by pixel:
//!
//! - embedded-graphics' own `Framebuffer`, where its layout is the format's
//!   (Bgr565 in either byte order, Gray4 and Gray2 leftmost in the high
//!   bits, and `BinaryMsb` for comparison);
//! - otherwise a per-pixel packing written here from the format's
//!   definition ([`Put`]).
//!
//! Rectangles, spans, pixels, triangles and lines (through the
//! framebuffer's own `SpanSink` with `draw_spans` and through
//! `DrawTargetSink` with `draw`) must leave identical bytes, padding and
//! every pixel outside the drawing included, and read back the same
//! colours. Spans start and end at every sub-byte offset.

#[path = "common/rng.rs"]
mod rng;

use core::{convert::Infallible, fmt::Debug, marker::PhantomData};

use embedded_graphics::{
    framebuffer::{buffer_size as eg_size, Framebuffer as EgFramebuffer},
    pixelcolor::raw::{BigEndian, LittleEndian},
};
use embedded_graphics_core::{
    image::GetPixel,
    pixelcolor::{
        Bgr565, BinaryColor, Gray2, Gray4, GrayColor, PixelColor, Rgb565, Rgb666, RgbColor,
    },
    prelude::*,
    primitives::Rectangle,
    Pixel,
};
use embedded_raster::{
    framebuffer::{
        buffer_size, Bgr565Be, Bgr565Le, BinaryMsb, Gray2Lsb, Gray2Msb, Gray4Lsb, Gray4Msb,
        PixelFormat, Rgb565Be, Rgb666Bytes,
    },
    DrawTargetSink, Framebuffer, Line, Span, SpanDrawable, SpanSink, Triangle, Vertex,
};
use proptest::prelude::*;
use rng::Rng;

// ---------------------------------------------------------------------------
// References.

/// A target drawn pixel by pixel, whose bytes are what the format under
/// test must hold.
trait Reference: DrawTarget<Error = Infallible> + Sized {
    fn blank() -> Self;
    fn bytes(&self) -> &[u8];
    fn bytes_mut(&mut self) -> &mut [u8];
    fn get(&self, p: Point) -> Option<Self::Color>;
}

/// embedded-graphics' framebuffer: its `draw_iter` sets one pixel at a
/// time, and its `fill_solid` is the trait's default, `draw_iter` over
/// the area's points.
impl<C, BO, const W: usize, const H: usize, const N: usize> Reference
    for EgFramebuffer<C, C::Raw, BO, W, H, N>
where
    C: PixelColor,
    Self: DrawTarget<Color = C, Error = Infallible> + GetPixel<Color = C>,
{
    fn blank() -> Self {
        Self::new()
    }
    fn bytes(&self) -> &[u8] {
        self.data()
    }
    fn bytes_mut(&mut self) -> &mut [u8] {
        self.data_mut()
    }
    fn get(&self, p: Point) -> Option<C> {
        GetPixel::pixel(self, p)
    }
}

/// A format's definition, one pixel at a time, for the layouts
/// embedded-graphics does not have.
trait Put {
    type Color: PixelColor;
    const BITS: usize;
    /// Writes pixel `x` (inside) into its row.
    fn put(row: &mut [u8], x: usize, c: Self::Color);
    /// Reads pixel `x` (inside) from its row.
    fn get(row: &[u8], x: usize) -> Self::Color;
}

/// `RRRRRR00 GGGGGG00 BBBBBB00` at bytes `3x..3x + 3`.
struct Rgb666Def;

impl Put for Rgb666Def {
    type Color = Rgb666;
    const BITS: usize = 24;
    fn put(row: &mut [u8], x: usize, c: Rgb666) {
        row[3 * x] = c.r() << 2;
        row[3 * x + 1] = c.g() << 2;
        row[3 * x + 2] = c.b() << 2;
    }
    fn get(row: &[u8], x: usize) -> Rgb666 {
        Rgb666::new(row[3 * x] >> 2, row[3 * x + 1] >> 2, row[3 * x + 2] >> 2)
    }
}

/// Pixel `x` in bits `shift..shift + BITS` of byte `x / (8 / BITS)`,
/// `shift = BITS * (x % (8 / BITS))`: leftmost at the bottom.
struct LowFirst<C>(PhantomData<C>);

macro_rules! low_first {
    ($color:ident, $bits:literal) => {
        impl Put for LowFirst<$color> {
            type Color = $color;
            const BITS: usize = $bits;
            fn put(row: &mut [u8], x: usize, c: $color) {
                let per_byte = 8 / $bits;
                let shift = $bits * (x % per_byte);
                let mask = ((1u8 << $bits) - 1) << shift;
                let byte = &mut row[x / per_byte];
                *byte = (*byte & !mask) | (c.luma() << shift);
            }
            fn get(row: &[u8], x: usize) -> $color {
                let per_byte = 8 / $bits;
                let shift = $bits * (x % per_byte);
                $color::new((row[x / per_byte] >> shift) & ((1 << $bits) - 1))
            }
        }
    };
}

low_first!(Gray4, 4);
low_first!(Gray2, 2);

/// A `W` x `H` framebuffer of [`Put`] pixels, rows padded to whole bytes.
struct Hand<P, const W: usize, const H: usize> {
    bytes: Vec<u8>,
    def: PhantomData<P>,
}

impl<P: Put, const W: usize, const H: usize> Hand<P, W, H> {
    const STRIDE: usize = (W * P::BITS).div_ceil(8);

    fn inside(p: Point) -> Option<(usize, usize)> {
        let (x, y) = (usize::try_from(p.x).ok()?, usize::try_from(p.y).ok()?);
        (x < W && y < H).then_some((x, y))
    }
}

impl<P: Put, const W: usize, const H: usize> OriginDimensions for Hand<P, W, H> {
    fn size(&self) -> Size {
        Size::new(W as u32, H as u32)
    }
}

impl<P: Put, const W: usize, const H: usize> DrawTarget for Hand<P, W, H> {
    type Color = P::Color;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<P::Color>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            if let Some((x, y)) = Self::inside(p) {
                P::put(&mut self.bytes[y * Self::STRIDE..][..Self::STRIDE], x, c);
            }
        }
        Ok(())
    }
}

impl<P: Put, const W: usize, const H: usize> Reference for Hand<P, W, H> {
    fn blank() -> Self {
        Self {
            bytes: vec![0; Self::STRIDE * H],
            def: PhantomData,
        }
    }
    fn bytes(&self) -> &[u8] {
        &self.bytes
    }
    fn bytes_mut(&mut self) -> &mut [u8] {
        &mut self.bytes
    }
    fn get(&self, p: Point) -> Option<P::Color> {
        let (x, y) = Self::inside(p)?;
        Some(P::get(&self.bytes[y * Self::STRIDE..][..Self::STRIDE], x))
    }
}

// ---------------------------------------------------------------------------
// Colours.

trait Arb: PixelColor + Debug {
    fn arb() -> BoxedStrategy<Self>;
}

impl Arb for Bgr565 {
    fn arb() -> BoxedStrategy<Self> {
        prop_oneof![
            4 => (0u8..32, 0u8..64, 0u8..32).prop_map(|(r, g, b)| Bgr565::new(r, g, b)),
            1 => Just(Bgr565::WHITE),
            1 => Just(Bgr565::new(8, 0, 1)), // 0x0808: both bytes equal
        ]
        .boxed()
    }
}

impl Arb for Rgb666 {
    fn arb() -> BoxedStrategy<Self> {
        prop_oneof![
            3 => (0u8..64, 0u8..64, 0u8..64).prop_map(|(r, g, b)| Rgb666::new(r, g, b)),
            1 => (0u8..64).prop_map(|v| Rgb666::new(v, v, v)), // uniform bytes
        ]
        .boxed()
    }
}

impl Arb for Gray4 {
    fn arb() -> BoxedStrategy<Self> {
        (0u8..16).prop_map(Gray4::new).boxed()
    }
}

impl Arb for Gray2 {
    fn arb() -> BoxedStrategy<Self> {
        (0u8..4).prop_map(Gray2::new).boxed()
    }
}

impl Arb for BinaryColor {
    fn arb() -> BoxedStrategy<Self> {
        any::<bool>().prop_map(BinaryColor::from).boxed()
    }
}

// ---------------------------------------------------------------------------
// Drawing the same thing on both.

#[derive(Debug, Clone)]
enum Op<C> {
    /// `fill_solid`.
    Solid(Rectangle, C),
    /// `fill_contiguous` with these colours.
    Contiguous(Rectangle, Vec<C>),
    /// `draw_iter`.
    Pixels(Vec<(Point, C)>),
    /// `clear`.
    Clear(C),
    /// `SpanSink::fill_span` with a span inside the framebuffer.
    Span(i32, i32, i32, C),
    /// A triangle with 20.12 vertices.
    Triangle([(i32, i32); 3], C),
    /// A line of this width.
    Line(Point, Point, u32, C),
}

fn arb_op<C: Arb + Copy + 'static>(w: i32, h: i32) -> impl Strategy<Value = Op<C>> {
    let point = move || (-6..w + 6, -6..h + 6).prop_map(|(x, y)| Point::new(x, y));
    let rect = move || {
        (point(), 0..w as u32 + 12, 0..h as u32 + 12)
            .prop_map(|(p, sw, sh)| Rectangle::new(p, Size::new(sw, sh)))
    };
    let span = (0..h, 0..=w, 0..=w).prop_map(|(y, a, b)| (y, a.min(b), a.max(b)));
    let raw = move || (-6 * 4096..(w + 6) * 4096, -6 * 4096..(h + 6) * 4096);
    prop_oneof![
        3 => (rect(), C::arb()).prop_map(|(r, c)| Op::Solid(r, c)),
        2 => (rect(), prop::collection::vec(C::arb(), 0..80))
            .prop_map(|(r, cs)| Op::Contiguous(r, cs)),
        2 => prop::collection::vec((point(), C::arb()), 0..16).prop_map(Op::Pixels),
        1 => C::arb().prop_map(Op::Clear),
        3 => (span, C::arb()).prop_map(|((y, a, b), c)| Op::Span(y, a, b, c)),
        3 => ([raw(), raw(), raw()], C::arb()).prop_map(|(v, c)| Op::Triangle(v, c)),
        3 => (point(), point(), 0u32..4, C::arb()).prop_map(|(a, b, wd, c)| Op::Line(a, b, wd, c)),
    ]
}

/// Bytes from a seed, to start every framebuffer from the same noise.
fn noise(seed: u64, bytes: &mut [u8]) {
    let mut rng = Rng(seed | 1);
    for b in bytes {
        *b = rng.next() as u8;
    }
}

/// Applies `ops`, from the same random bytes, to a framebuffer through
/// its own `SpanSink` (`draw_spans`), to a second one through
/// `DrawTargetSink` (`draw`), and to the reference through
/// `DrawTargetSink` and per-pixel `draw_iter`; compares the bytes and
/// every pixel's colour after each op.
fn compare<F, R, const W: usize, const H: usize, const N: usize>(
    seed: u64,
    ops: &[Op<F::Color>],
) -> Result<(), TestCaseError>
where
    F: PixelFormat<Color: Copy + Debug + PartialEq>,
    R: Reference<Color = F::Color>,
{
    let mut fb = Framebuffer::<F, W, H, N>::new();
    noise(seed, fb.as_bytes_mut());
    let mut via_target = fb.clone();
    let mut reference = R::blank();
    prop_assert_eq!(reference.bytes().len(), N);
    reference.bytes_mut().copy_from_slice(fb.as_bytes());
    for op in ops {
        match op {
            Op::Solid(r, c) => {
                fb.fill_solid(r, *c).unwrap();
                via_target.fill_solid(r, *c).unwrap();
                reference.fill_solid(r, *c).unwrap();
            }
            Op::Contiguous(r, cs) => {
                fb.fill_contiguous(r, cs.iter().copied()).unwrap();
                via_target.fill_contiguous(r, cs.iter().copied()).unwrap();
                let points = r.points().zip(cs.iter().copied());
                reference
                    .draw_iter(points.map(|(p, c)| Pixel(p, c)))
                    .unwrap();
            }
            Op::Pixels(ps) => {
                let pixels = || ps.iter().map(|&(p, c)| Pixel(p, c));
                fb.draw_iter(pixels()).unwrap();
                via_target.draw_iter(pixels()).unwrap();
                reference.draw_iter(pixels()).unwrap();
            }
            Op::Clear(c) => {
                fb.clear(*c).unwrap();
                via_target.clear(*c).unwrap();
                reference.clear(*c).unwrap();
            }
            &Op::Span(y, x_start, x_end, c) => {
                let span = Span { y, x_start, x_end };
                SpanSink::fill_span(&mut fb, span, c).unwrap();
                DrawTargetSink::new(&mut via_target)
                    .fill_span(span, c)
                    .unwrap();
                let row = Rectangle::new(
                    Point::new(x_start, y),
                    Size::new((x_end - x_start) as u32, 1),
                );
                reference
                    .draw_iter(row.points().map(|p| Pixel(p, c)))
                    .unwrap();
            }
            &Op::Triangle([a, b, v], c) => {
                let [a, b, v] = [a, b, v].map(|(x, y)| Vertex::from_raw(x, y));
                let shape = Triangle::new(a, b, v).fill(c);
                shape.draw_spans(&mut fb).unwrap();
                shape.draw(&mut via_target).unwrap();
                shape
                    .draw_spans(&mut DrawTargetSink::new(&mut reference))
                    .unwrap();
            }
            &Op::Line(a, b, width, c) => {
                let shape = Line::new(a, b).stroke(c).stroke_width(width);
                shape.draw_spans(&mut fb).unwrap();
                shape.draw(&mut via_target).unwrap();
                shape
                    .draw_spans(&mut DrawTargetSink::new(&mut reference))
                    .unwrap();
            }
        }
        prop_assert_eq!(fb.as_bytes(), reference.bytes(), "after {:?}", op);
        prop_assert_eq!(via_target.as_bytes(), reference.bytes(), "after {:?}", op);
        for y in -1..=H as i32 {
            for x in -1..=W as i32 {
                let p = Point::new(x, y);
                prop_assert_eq!(fb.pixel(p), reference.get(p), "{:?} after {:?}", p, op);
            }
        }
    }
    Ok(())
}

/// A proptest of [`compare`] for format `$f` at `$w` x `$h` against
/// reference `$r`.
macro_rules! compare_test {
    ($name:ident, $f:ty, $r:ty, $w:literal, $h:literal) => {
        proptest! {
            #[test]
            fn $name(
                seed in any::<u64>(),
                ops in prop::collection::vec(
                    arb_op::<<$f as PixelFormat>::Color>($w, $h),
                    1..10,
                ),
            ) {
                compare::<$f, $r, $w, $h, { buffer_size::<$f>($w, $h) }>(seed, &ops)?;
            }
        }
    };
}

/// embedded-graphics' framebuffer of colour `$c` and byte order `$bo`.
macro_rules! eg {
    ($c:ty, $bo:ty, $w:literal, $h:literal) => {
        EgFramebuffer<$c, <$c as PixelColor>::Raw, $bo, $w, $h, { eg_size::<$c>($w, $h) }>
    };
}

compare_test!(
    bgr565le_vs_eg_13x5,
    Bgr565Le,
    eg!(Bgr565, LittleEndian, 13, 5),
    13,
    5
);
compare_test!(
    bgr565le_vs_eg_40x3,
    Bgr565Le,
    eg!(Bgr565, LittleEndian, 40, 3),
    40,
    3
);
compare_test!(
    bgr565be_vs_eg_13x5,
    Bgr565Be,
    eg!(Bgr565, BigEndian, 13, 5),
    13,
    5
);
compare_test!(
    bgr565be_vs_eg_40x3,
    Bgr565Be,
    eg!(Bgr565, BigEndian, 40, 3),
    40,
    3
);
compare_test!(
    gray4msb_vs_eg_13x5,
    Gray4Msb,
    eg!(Gray4, BigEndian, 13, 5),
    13,
    5
);
compare_test!(
    gray4msb_vs_eg_40x3,
    Gray4Msb,
    eg!(Gray4, BigEndian, 40, 3),
    40,
    3
);
compare_test!(
    gray2msb_vs_eg_13x5,
    Gray2Msb,
    eg!(Gray2, BigEndian, 13, 5),
    13,
    5
);
compare_test!(
    gray2msb_vs_eg_42x3,
    Gray2Msb,
    eg!(Gray2, BigEndian, 42, 3),
    42,
    3
);
compare_test!(
    binary_vs_eg_13x5,
    BinaryMsb,
    eg!(BinaryColor, BigEndian, 13, 5),
    13,
    5
);
compare_test!(rgb666_vs_hand_13x5, Rgb666Bytes, Hand<Rgb666Def, 13, 5>, 13, 5);
compare_test!(rgb666_vs_hand_40x3, Rgb666Bytes, Hand<Rgb666Def, 40, 3>, 40, 3);
compare_test!(
    gray4lsb_vs_hand_13x5,
    Gray4Lsb,
    Hand<LowFirst<Gray4>, 13, 5>,
    13,
    5
);
compare_test!(
    gray4lsb_vs_hand_40x3,
    Gray4Lsb,
    Hand<LowFirst<Gray4>, 40, 3>,
    40,
    3
);
compare_test!(
    gray2lsb_vs_hand_13x5,
    Gray2Lsb,
    Hand<LowFirst<Gray2>, 13, 5>,
    13,
    5
);
compare_test!(
    gray2lsb_vs_hand_42x3,
    Gray2Lsb,
    Hand<LowFirst<Gray2>, 42, 3>,
    42,
    3
);

// ---------------------------------------------------------------------------
// Every span of a row, every sub-byte offset.

/// Every span `start..end` of row 1 of a noisy `W` x 3 framebuffer, in
/// each of `colors`, through `SpanSink::fill_span` and through the
/// format's `fill_span` on the row alone, against the reference's
/// per-pixel writes: the bytes outside the span (the other pixels of its
/// first and last bytes, padding, other rows) keep their noise.
fn every_span<F, R, const W: usize, const N: usize>(colors: &[F::Color])
where
    F: PixelFormat<Color: Copy + Debug + PartialEq>,
    R: Reference<Color = F::Color>,
{
    let stride = N / 3;
    let mut seed = 1;
    for start in 0..=W {
        for end in start..=W {
            for &c in colors {
                seed += 1;
                let mut fb = Framebuffer::<F, W, 3, N>::new();
                noise(seed, fb.as_bytes_mut());
                let mut row = fb.as_bytes()[stride..2 * stride].to_vec();
                let mut reference = R::blank();
                reference.bytes_mut().copy_from_slice(fb.as_bytes());
                let span = Span {
                    y: 1,
                    x_start: start as i32,
                    x_end: end as i32,
                };
                SpanSink::fill_span(&mut fb, span, c).unwrap();
                F::fill_span(&mut row, start..end, c);
                let pixels = (start..end).map(|x| Pixel(Point::new(x as i32, 1), c));
                reference.draw_iter(pixels).unwrap();
                let what = format!("{} {start}..{end} {c:?}", core::any::type_name::<F>());
                assert_eq!(fb.as_bytes(), reference.bytes(), "{what}");
                assert_eq!(row, reference.bytes()[stride..2 * stride], "{what}");
            }
        }
    }
}

#[test]
fn spans_at_every_sub_byte_offset() {
    let gray4 = [Gray4::new(0), Gray4::new(0xF), Gray4::new(0x6)];
    let gray2 = [Gray2::new(0), Gray2::new(3), Gray2::new(1)];
    every_span::<Gray4Msb, eg!(Gray4, BigEndian, 13, 3), 13, { buffer_size::<Gray4Msb>(13, 3) }>(
        &gray4,
    );
    every_span::<Gray4Lsb, Hand<LowFirst<Gray4>, 13, 3>, 13, { buffer_size::<Gray4Lsb>(13, 3) }>(
        &gray4,
    );
    every_span::<Gray2Msb, eg!(Gray2, BigEndian, 15, 3), 15, { buffer_size::<Gray2Msb>(15, 3) }>(
        &gray2,
    );
    every_span::<Gray2Lsb, Hand<LowFirst<Gray2>, 15, 3>, 15, { buffer_size::<Gray2Lsb>(15, 3) }>(
        &gray2,
    );
    every_span::<
        BinaryMsb,
        eg!(BinaryColor, BigEndian, 19, 3),
        19,
        { buffer_size::<BinaryMsb>(19, 3) },
    >(&[BinaryColor::On, BinaryColor::Off]);
    // Byte formats: uniform and mixed bytes, short spans and spans of 16
    // pixels or more (the word path on 32-bit ARM).
    let bgr = [Bgr565::new(8, 0, 1), Bgr565::new(31, 7, 3), Bgr565::BLACK];
    every_span::<Bgr565Le, eg!(Bgr565, LittleEndian, 21, 3), 21, { buffer_size::<Bgr565Le>(21, 3) }>(
        &bgr,
    );
    every_span::<Bgr565Be, eg!(Bgr565, BigEndian, 21, 3), 21, { buffer_size::<Bgr565Be>(21, 3) }>(
        &bgr,
    );
    every_span::<Rgb666Bytes, Hand<Rgb666Def, 21, 3>, 21, { buffer_size::<Rgb666Bytes>(21, 3) }>(
        &[Rgb666::new(9, 9, 9), Rgb666::new(63, 1, 40)],
    );
}

// ---------------------------------------------------------------------------
// Layouts written out by hand.

fn rect(x: i32, y: i32, w: u32, h: u32) -> Rectangle {
    Rectangle::new(Point::new(x, y), Size::new(w, h))
}

#[test]
fn bgr565_is_rgb565_with_red_and_blue_swapped() {
    // 10101 110011 01110: blue 0b10101 on top.
    let c = Bgr565::new(0b01110, 0b110011, 0b10101);
    let mut le = Framebuffer::<Bgr565Le, 2, 1, 4>::new();
    let mut be = Framebuffer::<Bgr565Be, 2, 1, 4>::new();
    Pixel(Point::new(1, 0), c).draw(&mut le).unwrap();
    be.fill_solid(&rect(1, 0, 9, 9), c).unwrap();
    assert_eq!(le.as_bytes(), [0, 0, 0x6E, 0xAE]);
    assert_eq!(be.as_bytes(), [0, 0, 0xAE, 0x6E]);
    // The same bytes as the Rgb565 colour with the channels swapped.
    let mut rgb = Framebuffer::<Rgb565Be, 2, 1, 4>::new();
    Pixel(Point::new(1, 0), Rgb565::new(0b10101, 0b110011, 0b01110))
        .draw(&mut rgb)
        .unwrap();
    assert_eq!(rgb.as_bytes(), be.as_bytes());
}

#[test]
fn rgb666_channels_in_the_high_bits() {
    let mut fb = Framebuffer::<Rgb666Bytes, 3, 1, 9>::new();
    fb.fill_contiguous(
        &rect(0, 0, 3, 1),
        [
            Rgb666::new(0b111111, 0, 0),
            Rgb666::new(0, 0b000001, 0),
            Rgb666::new(0b100000, 0b010101, 0b101010),
        ],
    )
    .unwrap();
    assert_eq!(
        fb.as_bytes(),
        [0xFC, 0, 0, 0, 0x04, 0, 0x80, 0b0101_0100, 0b1010_1000]
    );
    // The low 2 bits are ignored when read.
    fb.as_bytes_mut()[0] = 0xFF;
    assert_eq!(fb.pixel(Point::zero()), Some(Rgb666::new(63, 0, 0)));
}

#[test]
fn gray_nibble_and_bit_orders() {
    let values = [0x1, 0xA, 0xF].map(Gray4::new);
    let mut msb = Framebuffer::<Gray4Msb, 3, 1, 2>::new();
    let mut lsb = Framebuffer::<Gray4Lsb, 3, 1, 2>::new();
    msb.fill_contiguous(&rect(0, 0, 3, 1), values).unwrap();
    lsb.fill_contiguous(&rect(0, 0, 3, 1), values).unwrap();
    assert_eq!(msb.as_bytes(), [0x1A, 0xF0]);
    assert_eq!(lsb.as_bytes(), [0xA1, 0x0F]);

    let values = [1, 2, 3, 0, 3].map(Gray2::new);
    let mut msb = Framebuffer::<Gray2Msb, 5, 1, 2>::new();
    let mut lsb = Framebuffer::<Gray2Lsb, 5, 1, 2>::new();
    msb.fill_contiguous(&rect(0, 0, 5, 1), values).unwrap();
    lsb.fill_contiguous(&rect(0, 0, 5, 1), values).unwrap();
    assert_eq!(msb.as_bytes(), [0b01_10_11_00, 0b11_00_00_00]);
    assert_eq!(lsb.as_bytes(), [0b00_11_10_01, 0b00_00_00_11]);
}

#[test]
fn gray_padding_is_never_drawn() {
    let mut fb = Framebuffer::<Gray4Msb, 3, 2, 4>::new();
    fb.as_bytes_mut().fill(0xFF);
    fb.clear(Gray4::BLACK).unwrap();
    fb.fill_solid(&rect(-5, -5, 99, 99), Gray4::new(0)).unwrap();
    assert_eq!(fb.as_bytes(), [0, 0x0F, 0, 0x0F]);

    let mut fb = Framebuffer::<Gray4Lsb, 3, 2, 4>::new();
    fb.as_bytes_mut().fill(0xFF);
    fb.fill_contiguous(&rect(0, 0, 3, 2), core::iter::repeat(Gray4::BLACK))
        .unwrap();
    assert_eq!(fb.as_bytes(), [0, 0xF0, 0, 0xF0]);

    let mut fb = Framebuffer::<Gray2Lsb, 5, 2, 4>::new();
    fb.as_bytes_mut().fill(0xFF);
    fb.clear(Gray2::BLACK).unwrap();
    assert_eq!(fb.as_bytes(), [0, 0b1111_1100, 0, 0b1111_1100]);
}

#[test]
fn sub_byte_rows_merge_only_without_padding() {
    // 8 Gray4 pixels a row: 4 whole bytes, rows filled as one.
    let mut fb = Framebuffer::<Gray4Msb, 8, 3, { buffer_size::<Gray4Msb>(8, 3) }>::new();
    assert_eq!(fb.as_bytes().len(), 12);
    fb.clear(Gray4::new(0x7)).unwrap();
    assert!(fb.as_bytes().iter().all(|&b| b == 0x77));
    // 6 Gray2 pixels a row: 2 bytes, the last half padding.
    let mut fb = Framebuffer::<Gray2Msb, 6, 3, { buffer_size::<Gray2Msb>(6, 3) }>::new();
    fb.clear(Gray2::WHITE).unwrap();
    assert_eq!(fb.as_bytes(), [0xFF, 0xF0, 0xFF, 0xF0, 0xFF, 0xF0]);
}

#[test]
fn static_framebuffers_of_the_new_formats() {
    static OLED: Framebuffer<Gray4Msb, 256, 64, { buffer_size::<Gray4Msb>(256, 64) }> =
        Framebuffer::new();
    static PANEL: Framebuffer<Rgb666Bytes, 4, 4, { buffer_size::<Rgb666Bytes>(4, 4) }> =
        Framebuffer::new();
    assert_eq!(OLED.as_bytes().len(), 8192);
    assert_eq!(OLED.pixel(Point::new(255, 63)), Some(Gray4::BLACK));
    assert_eq!(PANEL.as_bytes().len(), 48);
}

/// `PixelFormat::fill_line` at any stride (found by a robustness audit):
/// the byte formats walked a line by an index that overflowed `isize` at
/// huge strides (a panic with overflow checks, a wrapped write into
/// pixels already drawn without), took rows of `stride / B` whole pixels
/// when `stride` is not a multiple of `B`, and dropped a whole line whose
/// first pixel's offset overflowed. Each pixel must land at `y stride +
/// x B`, inside its row and the buffer, or nowhere.
#[test]
fn lines_at_any_stride() {
    use embedded_graphics_core::pixelcolor::{Gray8, Rgb888};
    use embedded_raster::framebuffer::{Gray8Bytes, Rgb565Le, Rgb888Bytes};

    /// The bytes expected: every pixel of `line` within `clip` whose bytes
    /// lie in its row and in `len`, set to `px`.
    fn expected<const B: usize>(
        len: usize,
        stride: usize,
        line: Line,
        clip: &Rectangle,
        px: [u8; B],
    ) -> Vec<u8> {
        let mut want = vec![0u8; len];
        let (b, stride, len) = (B as i128, stride as i128, len as i128);
        for p in line.pixels(clip).into_iter().flatten() {
            let (x, y) = (i128::from(p.x), i128::from(p.y));
            let at = y * stride + x * b;
            if x >= 0 && y >= 0 && (x + 1) * b <= stride && at + b <= len {
                want[at as usize..(at + b) as usize].copy_from_slice(&px);
            }
        }
        want
    }
    fn check<F: PixelFormat, const B: usize>(color: F::Color, px: [u8; B]) {
        let near = Rectangle::new(Point::zero(), Size::new(1000, 1000));
        let around = Rectangle::new(Point::new(-500, -500), Size::new(1000, 1000));
        let far = Rectangle::new(Point::new(-3, i32::MAX - 999), Size::new(1000, 1000));
        let cases = [
            (Line::new(Point::new(0, 0), Point::new(0, 3)), near),
            (Line::new(Point::new(0, 0), Point::new(5, 2)), near),
            // Upwards, from far below: the last pixel is the first row's.
            (Line::new(Point::new(0, 999), Point::new(1, 0)), near),
            (Line::new(Point::new(7, 998), Point::new(2, 0)), near),
            // Through the origin from negative coordinates, which are
            // dropped.
            (Line::new(Point::new(-3, -2), Point::new(4, 3)), around),
            (Line::new(Point::new(-2, -5), Point::new(2, 5)), around),
            // Far down, where an offset leaves `isize` at large strides.
            (
                Line::new(Point::new(0, i32::MAX - 10), Point::new(5, i32::MAX)),
                far,
            ),
        ];
        // Rows of at least 8 pixels (the lines' columns reach 7; a pixel
        // past its row's end is the caller's to clip), and strides too
        // large for an index to reach the second row.
        let strides = [
            8 * B,
            8 * B + 1,
            8 * B + 2,
            40_000 * B,
            (u32::MAX as usize).saturating_mul(B),
            usize::MAX / 3 + 1,
            usize::MAX / 2,
            isize::MAX as usize,
            usize::MAX,
        ];
        for (line, clip) in cases {
            for stride in strides {
                let mut buffer = vec![0u8; 40];
                F::fill_line(&mut buffer, stride, line.pixels(&clip).unwrap(), color);
                assert_eq!(
                    buffer,
                    expected(40, stride, line, &clip, px),
                    "{line:?} at stride {stride}"
                );
            }
        }
    }
    check::<Gray8Bytes, 1>(Gray8::new(7), [7]);
    check::<Rgb565Le, 2>(
        Rgb565::new(1, 2, 3),
        Rgb565::new(1, 2, 3).into_storage().to_le_bytes(),
    );
    check::<Rgb888Bytes, 3>(Rgb888::new(4, 5, 6), [4, 5, 6]);
}
