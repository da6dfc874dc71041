//! Fixed-point 3D for small meshes: sine and cosine from a quarter-wave
//! table, rotation, perspective projection to [`Vertex`]es and `u16`
//! depths, and an allocation-free latitude/longitude sphere generator.
//!
//! Everything is integer: positions and matrix entries are Q15 (`32768` is
//! 1.0), angles are `u16` fractions of a turn (`65536` is a full turn), no
//! floating point and no `libm`.
//!
//! # Ranges
//!
//! Every function takes any value of its argument types without panicking
//! or wrapping: products are formed in `i64`/`i128` where they cannot
//! overflow, and a result that does not fit its `i32` is saturated
//! ([`Vec3::dot`], [`Rotation::apply`]) or `None`
//! ([`Vec3::checked_dot`], [`Rotation::checked_apply`],
//! [`Camera::project`]). Each function's docs give the range in which its
//! result is exact.

use crate::vertex::Vertex;

/// 1.0 in Q15, the fixed-point format of [`Vec3`] and of [`sin_cos`].
pub const ONE: i32 = 1 << 15;

/// A quarter turn in the angle units of [`sin_cos`].
pub const QUARTER_TURN: u16 = 1 << 14;

/// `round(32768 sin(k pi / 256))` for `k = 0..=128`: a quarter wave.
const SINE: [u16; 129] = [
    0, 402, 804, 1206, 1608, 2009, 2411, 2811, 3212, 3612, 4011, 4410, 4808, 5205, 5602, 5998,
    6393, 6787, 7180, 7571, 7962, 8351, 8740, 9127, 9512, 9896, 10279, 10660, 11039, 11417, 11793,
    12167, 12540, 12910, 13279, 13646, 14010, 14373, 14733, 15091, 15447, 15800, 16151, 16500,
    16846, 17190, 17531, 17869, 18205, 18538, 18868, 19195, 19520, 19841, 20160, 20475, 20788,
    21097, 21403, 21706, 22006, 22302, 22595, 22884, 23170, 23453, 23732, 24008, 24279, 24548,
    24812, 25073, 25330, 25583, 25833, 26078, 26320, 26557, 26791, 27020, 27246, 27467, 27684,
    27897, 28106, 28311, 28511, 28707, 28899, 29086, 29269, 29448, 29622, 29792, 29957, 30118,
    30274, 30425, 30572, 30715, 30853, 30986, 31114, 31238, 31357, 31471, 31581, 31686, 31786,
    31881, 31972, 32058, 32138, 32214, 32286, 32352, 32413, 32470, 32522, 32568, 32610, 32647,
    32679, 32706, 32729, 32746, 32758, 32766, 32768,
];

/// `32768 sin(w pi / 32768)` for `w` in `0..=16384`, by linear
/// interpolation between table entries 128 units apart.
fn quarter(w: u32) -> i32 {
    let (i, f) = ((w >> 7) as usize, (w & 127) as i32);
    let a = i32::from(SINE[i]);
    let b = i32::from(SINE[(i + 1).min(128)]);
    a + (((b - a) * f + 64) >> 7)
}

/// Sine and cosine of `angle` (in units of a turn / 65536, any `u16`) in
/// Q15, both within `±ONE`.
///
/// Linear interpolation in a 129-entry quarter-wave table: each result is
/// within 2 units (`2^-14`) of the exact value (interpolation error at most
/// `(pi / 256)^2 / 8 * 32768 < 0.62`, plus two roundings of 1/2), checked
/// for every angle in the tests.
///
/// # Examples
///
/// ```
/// use embedded_raster::mesh::{sin_cos, ONE, QUARTER_TURN};
///
/// assert_eq!(sin_cos(0), (0, ONE));
/// assert_eq!(sin_cos(QUARTER_TURN), (ONE, 0));
/// let (s, c) = sin_cos(QUARTER_TURN / 3); // 30 degrees
/// assert!((s - ONE / 2).abs() <= 2 && (c - 28378).abs() <= 2);
/// ```
pub fn sin_cos(angle: u16) -> (i32, i32) {
    let sin = |a: u16| {
        let w = u32::from(a & (QUARTER_TURN - 1));
        match a >> 14 {
            0 => quarter(w),
            1 => quarter(16384 - w),
            2 => -quarter(w),
            _ => -quarter(16384 - w),
        }
    };
    (sin(angle), sin(angle.wrapping_add(QUARTER_TURN)))
}

/// A point or direction in Q15 fixed point.
///
/// # Examples
///
/// ```
/// use embedded_raster::mesh::{Vec3, ONE};
///
/// // One unit up, two away from the viewer.
/// let v = Vec3 { x: 0, y: ONE, z: 2 * ONE };
/// assert_eq!(v, Vec3::new(0, ONE, 2 * ONE));
/// assert_eq!(v.dot(v), 5 * ONE);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Vec3 {
    /// Right.
    pub x: i32,
    /// Up.
    pub y: i32,
    /// Away from the viewer.
    pub z: i32,
}

impl Vec3 {
    /// A vector from its components.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::mesh::Vec3;
    ///
    /// let v = Vec3::new(1, -2, 3);
    /// assert_eq!((v.x, v.y, v.z), (1, -2, 3));
    /// ```
    pub const fn new(x: i32, y: i32, z: i32) -> Self {
        Self { x, y, z }
    }

    /// The dot product, in Q15, rounded to nearest (ties up), saturated to
    /// `i32`.
    ///
    /// Any components are accepted: the sum of products is exact (in
    /// `i128`). The result is exact when it fits `i32`, which is always the
    /// case for components within `±2^22` (then `|d| <= 3 * 2^44 / 2^15 <
    /// 2^31`), or whenever one vector has length at most [`ONE`] and the
    /// other components within `±2^30`. Otherwise it saturates at
    /// `i32::MIN` or `i32::MAX`; [`checked_dot`](Self::checked_dot) says
    /// when.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::mesh::{Vec3, ONE};
    ///
    /// let half = Vec3::new(ONE / 2, 0, 0);
    /// assert_eq!(half.dot(Vec3::new(ONE, ONE, 0)), ONE / 2);
    /// let big = Vec3::new(1 << 25, 1 << 25, 0); // 2^36 in Q15: too big
    /// assert_eq!(big.dot(big), i32::MAX);
    /// ```
    pub fn dot(self, o: Self) -> i32 {
        let d = self.wide_dot(o);
        // Saturating: the clamped value fits, so the conversion cannot fail.
        i32::try_from(d.clamp(i32::MIN.into(), i32::MAX.into())).unwrap_or_default()
    }

    /// The dot product as [`dot`](Self::dot), or `None` if the rounded
    /// result does not fit `i32`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::mesh::{Vec3, ONE};
    ///
    /// let v = Vec3::new(ONE, -ONE, 2 * ONE);
    /// assert_eq!(v.checked_dot(v), Some(6 * ONE));
    /// let min = Vec3::new(i32::MIN, i32::MIN, i32::MIN);
    /// assert_eq!(min.checked_dot(min), None);
    /// ```
    pub fn checked_dot(self, o: Self) -> Option<i32> {
        i32::try_from(self.wide_dot(o)).ok()
    }

    /// The rounded Q15 dot product, exact: each product is below `2^62` in
    /// magnitude, the sum below `3 * 2^62 < 2^127`.
    fn wide_dot(self, o: Self) -> i128 {
        let p = |a: i32, b: i32| i128::from(a) * i128::from(b);
        let d = p(self.x, o.x) + p(self.y, o.y) + p(self.z, o.z);
        (d + (1 << 14)) >> 15
    }
}

/// A rotation matrix in Q15.
///
/// # Examples
///
/// ```
/// use embedded_raster::mesh::{Rotation, Vec3, ONE};
///
/// let swap = Rotation { m: [[0, ONE, 0], [ONE, 0, 0], [0, 0, ONE]] };
/// assert_eq!(swap.apply(Vec3::new(1, 2, 3)), Vec3::new(2, 1, 3));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rotation {
    /// Rows of the matrix, Q15. [`Rotation::new`] makes entries within
    /// `±ONE` and rows of length `ONE` (up to rounding); any entries are
    /// accepted by [`apply`](Self::apply).
    pub m: [[i32; 3]; 3],
}

impl Rotation {
    /// Turns by `yaw` about the vertical axis, then by `pitch` about the
    /// horizontal one (angles in turns / 65536).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::mesh::{Rotation, Vec3, ONE, QUARTER_TURN};
    ///
    /// let r = Rotation::new(QUARTER_TURN, 0);
    /// assert_eq!(r.apply(Vec3::new(ONE, 0, 0)), Vec3::new(0, 0, -ONE));
    /// ```
    pub fn new(yaw: u16, pitch: u16) -> Self {
        let (sy, cy) = sin_cos(yaw);
        let (sp, cp) = sin_cos(pitch);
        // Sines and cosines lie within ±ONE = ±2^15, so each product is
        // within ±2^30 and the rounded quotient within ±2^15: `as` is exact.
        let mul = |a: i32, b: i32| ((i64::from(a) * i64::from(b) + (1 << 14)) >> 15) as i32;
        // Rx(pitch) * Ry(yaw).
        Self {
            m: [
                [cy, 0, sy],
                [mul(sp, sy), cp, -mul(sp, cy)],
                [-mul(cp, sy), sp, mul(cp, cy)],
            ],
        }
    }

    /// The rotated vector, each component rounded as by [`Vec3::dot`] and
    /// saturated to `i32`.
    ///
    /// Any vector is accepted. For a rotation made by [`new`](Self::new)
    /// and components within `±2^30` the result is exact (no saturation):
    /// each row's entries sum to at most `sqrt(3) ONE + 10` in magnitude
    /// (the exact rotation's `sqrt(3) ONE`, plus [`sin_cos`]'s error of 2
    /// units per factor and 1/2 per rounded product), so a component is at
    /// most `2^30 (sqrt(3) + 2^-11) < 2^31`. Outside that
    /// range, use [`checked_apply`](Self::checked_apply) to detect
    /// saturation.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::mesh::{Rotation, Vec3, ONE, QUARTER_TURN};
    ///
    /// let r = Rotation::new(QUARTER_TURN / 2, 0); // 45 degrees about y
    /// let v = Vec3::new(i32::MAX, 0, i32::MAX);
    /// assert_eq!(r.apply(v).x, i32::MAX); // sqrt(2) i32::MAX, saturated
    /// ```
    pub fn apply(&self, v: Vec3) -> Vec3 {
        let row = |r: [i32; 3]| Vec3::new(r[0], r[1], r[2]).dot(v);
        Vec3::new(row(self.m[0]), row(self.m[1]), row(self.m[2]))
    }

    /// The rotated vector as [`apply`](Self::apply), or `None` if a
    /// component does not fit `i32`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::mesh::{Rotation, Vec3, ONE, QUARTER_TURN};
    ///
    /// let r = Rotation::new(QUARTER_TURN / 2, 0);
    /// assert!(r.checked_apply(Vec3::new(1 << 30, 0, 1 << 30)).is_some());
    /// assert_eq!(r.checked_apply(Vec3::new(i32::MAX, 0, i32::MAX)), None);
    /// ```
    pub fn checked_apply(&self, v: Vec3) -> Option<Vec3> {
        let row = |r: [i32; 3]| Vec3::new(r[0], r[1], r[2]).checked_dot(v);
        Some(Vec3::new(row(self.m[0])?, row(self.m[1])?, row(self.m[2])?))
    }
}

/// A pinhole camera at the origin looking along `+z`.
///
/// # Examples
///
/// A point on the optical axis lands on the centre; one twice as far
/// off the axis, at the same depth, lands twice as far from it.
///
/// ```
/// use embedded_raster::mesh::{Camera, Vec3, ONE};
///
/// let cam = Camera { focal: 64, centre: (80, 60), near: ONE / 4, far: 8 * ONE };
/// let at = |x: i32| cam.project(Vec3::new(x, 0, 4 * ONE)).unwrap().0.raw();
/// assert_eq!(at(0), (80 << 12, 60 << 12));
/// assert_eq!(at(ONE).0 - at(0).0, 16 << 12); // 64 px * 1 / 4
/// assert_eq!(at(2 * ONE).0 - at(0).0, 32 << 12);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Camera {
    /// Focal length in pixels: a point at depth `z` and height `y` lands
    /// `focal * y / z` px above the centre.
    pub focal: i32,
    /// Screen position of the optical axis, in pixels.
    pub centre: (i32, i32),
    /// Nearest and farthest depth (Q15 units, `0 < near < far`) mapped to
    /// the depth buffer's `0` and `65534`.
    pub near: i32,
    /// See [`near`](Self::near).
    pub far: i32,
}

impl Camera {
    /// Projects `p` (camera space, Q15) to a sub-pixel screen position and
    /// a depth for [`DepthBuffer`](crate::shade::DepthBuffer)s: `65534 far
    /// (z - near) / (z (far - near))`, clamped to `0..=65534`. It is affine
    /// in `1 / z`, so interpolating it linearly across a projected triangle
    /// is exact (perspective-correct depth). `None` if `z <= 0` or the
    /// position is outside the 20.12 range.
    ///
    /// Every field and point may be any `i32`: the position is computed in
    /// `i128` (`|focal 4096 x| < 2^75`, rounded halves up) and checked
    /// into `i32` as a whole, centre and offset together; the depth
    /// likewise (`|65534 far (z - near)| < 2^80`). Depth is 0 unless
    /// `0 < near < far`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::mesh::{Camera, Vec3, ONE};
    ///
    /// let cam = Camera { focal: 100, centre: (64, 64), near: ONE, far: 5 * ONE };
    /// let (v, z) = cam.project(Vec3::new(ONE, ONE, 2 * ONE)).unwrap();
    /// assert_eq!(v.raw(), (114 << 12, 14 << 12)); // y up on the plane, down on screen
    /// assert_eq!(cam.project(Vec3::new(0, 0, ONE)).unwrap().1, 0);
    /// assert_eq!(cam.project(Vec3::new(0, 0, 5 * ONE)).unwrap().1, 65534);
    /// assert!(z > 0 && z < 65534);
    /// ```
    pub fn project(&self, p: Vec3) -> Option<(Vertex, u16)> {
        if p.z <= 0 {
            return None;
        }
        let z = i128::from(p.z);
        let scale = i128::from(self.focal) * 4096;
        // focal 4096 p / z, rounded (halves up), from the centre: the sum
        // in `i128` (below 2^76), so that only the position must fit.
        let offset = |n: i32| (2 * scale * i128::from(n) + z).div_euclid(2 * z);
        let centre = |c: i32| i128::from(c) * 4096;
        let x = i32::try_from(centre(self.centre.0) + offset(p.x)).ok()?;
        let y = i32::try_from(centre(self.centre.1) - offset(p.y)).ok()?;
        let (near, far) = (i128::from(self.near), i128::from(self.far));
        let depth = if far > near && near > 0 {
            (65534 * far * (z - near) / (z * (far - near))).clamp(0, 65534)
        } else {
            0
        };
        Some((Vertex::from_raw(x, y), depth as u16))
    }
}

/// Why [`sphere`] could not build a mesh.
///
/// # Examples
///
/// ```
/// use embedded_raster::mesh::{sphere, MeshError, Vec3};
///
/// let (mut vertices, mut triangles) = ([Vec3::default(); 16], [[0u16; 3]; 16]);
/// assert_eq!(
///     sphere(4, 6, &mut vertices, &mut triangles),
///     Err(MeshError::StorageTooSmall { vertices: 20, triangles: 36 })
/// );
/// assert_eq!(sphere(1, 6, &mut vertices, &mut triangles), Err(MeshError::BadDivisions));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum MeshError {
    /// Fewer than 2 rings or 3 segments, or more vertices than `u16`
    /// indices reach.
    BadDivisions,
    /// The storage is too small: it needs this many vertices and triangles
    /// ([`sphere_size`]).
    StorageTooSmall {
        /// Vertices needed.
        vertices: usize,
        /// Triangles needed.
        triangles: usize,
    },
}

/// The number of vertices and triangles of [`sphere`]`(rings, segments)`:
/// `(2 + segments (rings - 1), 2 segments (rings - 1))`, each saturating at
/// `usize::MAX` (on 32-bit targets the largest divisions reach 2^33,
/// far past the 65,535 vertices [`sphere`] accepts).
///
/// # Examples
///
/// ```
/// use embedded_raster::mesh::sphere_size;
///
/// assert_eq!(sphere_size(8, 16), (114, 224));
/// // Exact where `usize` holds it, saturated where it does not.
/// let (v, t) = sphere_size(u16::MAX, u16::MAX);
/// assert_eq!(v as u64, (2 + 65_535 * 65_534u64).min(usize::MAX as u64));
/// assert_eq!(t as u64, (2 * 65_535 * 65_534u64).min(usize::MAX as u64));
/// ```
pub const fn sphere_size(rings: u16, segments: u16) -> (usize, usize) {
    // In `u64`: at most 2 * 65535 * 65534 < 2^33.
    let bands = (rings as u64).saturating_sub(1);
    let quads = segments as u64 * bands;
    (saturating_usize(2 + quads), saturating_usize(2 * quads))
}

/// `n` as a `usize`, or `usize::MAX` if it does not fit.
const fn saturating_usize(n: u64) -> usize {
    if n > usize::MAX as u64 {
        usize::MAX
    } else {
        n as usize
    }
}

/// Builds a unit sphere (radius [`ONE`]) by latitude and longitude into
/// caller-provided storage: `rings` bands from pole to pole (`rings - 1`
/// circles of latitude between the poles) and `segments` meridians.
/// Vertex 0 is the north pole `(0, ONE, 0)`, the last the south pole; each
/// vertex is also its own outward unit normal. Triangles are vertex index
/// triples `[a, b, c]`, all wound the same way: `(b - a) x (c - a)` points
/// outward, so after projection (y flips) outward faces have one sign of
/// area and back faces the other. Returns the numbers of vertices and triangles written
/// ([`sphere_size`]).
///
/// # Errors
///
/// [`MeshError`] for too few divisions or too little storage.
///
/// # Examples
///
/// ```
/// use embedded_raster::mesh::{sphere, sphere_size, Vec3, ONE};
///
/// let mut vertices = [Vec3::default(); 114];
/// let mut triangles = [[0u16; 3]; 224];
/// assert_eq!(sphere(8, 16, &mut vertices, &mut triangles), Ok(sphere_size(8, 16)));
/// assert_eq!(vertices[0], Vec3::new(0, ONE, 0));
/// // Every vertex is on the sphere, up to the trigonometry's rounding.
/// assert!(vertices.iter().all(|v| (v.dot(*v) - ONE).abs() < 8));
/// ```
pub fn sphere(
    rings: u16,
    segments: u16,
    vertices: &mut [Vec3],
    triangles: &mut [[u16; 3]],
) -> Result<(usize, usize), MeshError> {
    let (nv, nt) = sphere_size(rings, segments);
    if rings < 2 || segments < 3 || nv > usize::from(u16::MAX) {
        return Err(MeshError::BadDivisions);
    }
    if vertices.len() < nv || triangles.len() < nt {
        return Err(MeshError::StorageTooSmall {
            vertices: nv,
            triangles: nt,
        });
    }
    let (r, s) = (u32::from(rings), u32::from(segments));
    // Sines and cosines are within ±ONE: the rounded product is too, so
    // `as` is exact.
    let mul = |a: i32, b: i32| ((i64::from(a) * i64::from(b) + (1 << 14)) >> 15) as i32;
    vertices[0] = Vec3::new(0, ONE, 0);
    vertices[nv - 1] = Vec3::new(0, -ONE, 0);
    for i in 1..r {
        // Polar angle i / rings of a half turn.
        // `i < r` and `j < s <= 65535`: the angles are below 32768 and
        // 65536 (and `j * 65536 < 2^32`), so `as u16` is exact.
        let (sin_t, cos_t) = sin_cos((i * 32768 / r) as u16);
        for j in 0..s {
            let (sin_p, cos_p) = sin_cos((j * 65536 / s) as u16);
            let k = 1 + ((i - 1) * s + j) as usize;
            vertices[k] = Vec3::new(mul(sin_t, cos_p), cos_t, mul(sin_t, sin_p));
        }
    }
    // `nv <= 65535`, so every index fits in u16.
    let at = |i: u32, j: u32| (1 + (i - 1) * s + j % s) as u16;
    let south = (nv - 1) as u16;
    let mut t = 0;
    let mut push = |tri: [u16; 3]| {
        triangles[t] = tri;
        t += 1;
    };
    for j in 0..s {
        push([0, at(1, j + 1), at(1, j)]);
        for i in 1..r - 1 {
            push([at(i, j), at(i, j + 1), at(i + 1, j + 1)]);
            push([at(i, j), at(i + 1, j + 1), at(i + 1, j)]);
        }
        push([at(r - 1, j), at(r - 1, j + 1), south]);
    }
    Ok((nv, nt))
}
