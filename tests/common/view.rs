//! A `DrawTarget` placed anywhere in the `i32` plane, for the tests that
//! look at windows far from the origin.

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Dimensions, Point},
    primitives::Rectangle,
    Pixel,
};

/// A `DrawTarget` seen at `origin`: pixel `origin + p` of the view is
/// pixel `p` of `inner`, shifted in `i64`, so views sit anywhere,
/// the ends of the `i32` range included.
pub struct View<'a, D> {
    pub inner: &'a mut D,
    pub origin: Point,
}

impl<D: DrawTarget> View<'_, D> {
    fn shift(&self, p: Point) -> Point {
        let d = |a: i32, o: i32| {
            i32::try_from(i64::from(a) - i64::from(o)).unwrap_or_else(|_| {
                panic!(
                    "a write at {p:?}, far outside the view at {:?}",
                    self.origin
                )
            })
        };
        Point::new(d(p.x, self.origin.x), d(p.y, self.origin.y))
    }
}

impl<D: DrawTarget> Dimensions for View<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        Rectangle::new(self.origin, self.inner.bounding_box().size)
    }
}

impl<D: DrawTarget> DrawTarget for View<'_, D> {
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<D::Color>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), D::Error> {
        let shifted: Vec<_> = pixels
            .into_iter()
            .map(|Pixel(p, c)| Pixel(self.shift(p), c))
            .collect();
        self.inner.draw_iter(shifted)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: D::Color) -> Result<(), D::Error> {
        let area = Rectangle::new(self.shift(area.top_left), area.size);
        self.inner.fill_solid(&area, color)
    }

    /// Passed on whole, so that the inner target's own `fill_contiguous`
    /// (a `Framebuffer`'s, say) is the one tested.
    fn fill_contiguous<I: IntoIterator<Item = D::Color>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), D::Error> {
        let area = Rectangle::new(self.shift(area.top_left), area.size);
        self.inner.fill_contiguous(&area, colors)
    }
}
