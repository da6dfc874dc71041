//! Fixed-point 3D: trigonometry error, rotation, projection, the sphere.

use embedded_raster::mesh::{sin_cos, sphere, sphere_size, Camera, MeshError, Rotation, Vec3, ONE};

#[test]
fn sin_cos_within_2_units_at_every_angle() {
    let mut worst = 0.0f64;
    for a in 0..=u16::MAX {
        let (s, c) = sin_cos(a);
        let t = f64::from(a) / 65536.0 * core::f64::consts::TAU;
        let es = (f64::from(s) - 32768.0 * t.sin()).abs();
        let ec = (f64::from(c) - 32768.0 * t.cos()).abs();
        worst = worst.max(es).max(ec);
        assert!(es <= 2.0 && ec <= 2.0, "angle {a}: ({s}, {c})");
    }
    // The bound is not loose by much: interpolation does lose precision.
    assert!(worst > 0.5, "{worst}");
}

#[test]
fn rotations_keep_lengths() {
    for (yaw, pitch) in [(0u16, 0u16), (1000, 20000), (40000, 123), (65535, 32768)] {
        let r = Rotation::new(yaw, pitch);
        for v in [
            Vec3::new(ONE, 0, 0),
            Vec3::new(0, ONE, 0),
            Vec3::new(0, 0, ONE),
            Vec3::new(18918, 18918, 18918),
        ] {
            let w = r.apply(v);
            assert!(
                (w.dot(w) - v.dot(v)).abs() <= 16,
                "{yaw} {pitch}: {v:?} -> {w:?}"
            );
        }
    }
}

#[test]
fn sphere_storage_and_divisions() {
    let mut v = [Vec3::default(); 10];
    let mut t = [[0u16; 3]; 16];
    assert_eq!(sphere(1, 8, &mut v, &mut t), Err(MeshError::BadDivisions));
    assert_eq!(sphere(4, 2, &mut v, &mut t), Err(MeshError::BadDivisions));
    assert_eq!(
        sphere(400, 400, &mut v, &mut t),
        Err(MeshError::BadDivisions)
    );
    // Divisions whose counts pass 2^32 (they overflowed `usize` on 32-bit
    // targets: the i686 run of `.ci/run` checks that case).
    for (rings, segments) in [(40_000, 60_000), (u16::MAX, u16::MAX), (u16::MAX, 3)] {
        assert_eq!(
            sphere(rings, segments, &mut v, &mut t),
            Err(MeshError::BadDivisions)
        );
        let quads = u64::from(segments) * (u64::from(rings) - 1);
        let (nv, nt) = sphere_size(rings, segments);
        assert_eq!(nv as u64, (2 + quads).min(usize::MAX as u64));
        assert_eq!(nt as u64, (2 * quads).min(usize::MAX as u64));
    }
    assert_eq!(
        sphere(4, 8, &mut v, &mut t),
        Err(MeshError::StorageTooSmall {
            vertices: 26,
            triangles: 48
        })
    );
    assert_eq!(sphere(2, 4, &mut v, &mut t), Ok((6, 8)));
}

/// A closed, consistently wound mesh on the unit sphere: every edge is used
/// once in each direction, every normal points outward, the vertices are on
/// the sphere.
#[test]
fn sphere_is_closed_and_consistently_wound() {
    for (rings, segments) in [(2u16, 3u16), (3, 4), (8, 16), (17, 5), (40, 64)] {
        let (nv, nt) = sphere_size(rings, segments);
        let mut v = vec![Vec3::default(); nv];
        let mut t = vec![[0u16; 3]; nt];
        assert_eq!(sphere(rings, segments, &mut v, &mut t), Ok((nv, nt)));
        for p in &v {
            assert!((p.dot(*p) - ONE).abs() <= 8, "{p:?}");
        }
        let mut edges = std::collections::HashMap::new();
        for tri in &t {
            for k in 0..3 {
                *edges.entry((tri[k], tri[(k + 1) % 3])).or_insert(0) += 1;
            }
            let [a, b, c] = tri.map(|i| v[usize::from(i)]);
            let (u, w) = (
                [b.x - a.x, b.y - a.y, b.z - a.z].map(i64::from),
                [c.x - a.x, c.y - a.y, c.z - a.z].map(i64::from),
            );
            let n = [
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ];
            let out = n[0] * i64::from(a.x + b.x + c.x)
                + n[1] * i64::from(a.y + b.y + c.y)
                + n[2] * i64::from(a.z + b.z + c.z);
            assert!(out > 0, "{rings}x{segments}: {tri:?} winds inward");
        }
        for (&(a, b), &n) in &edges {
            assert_eq!(n, 1, "edge {a}-{b}");
            assert_eq!(edges.get(&(b, a)), Some(&1), "edge {a}-{b} has no twin");
        }
    }
}

#[test]
fn projection_centres_and_depths() {
    let cam = Camera {
        focal: 200,
        centre: (160, 120),
        near: ONE,
        far: 3 * ONE,
    };
    let (c, z) = cam.project(Vec3::new(0, 0, 2 * ONE)).unwrap();
    assert_eq!(c.raw(), (160 << 12, 120 << 12));
    // 1/z is halfway between 1/near and 1/far at z = 1.5: depth 32767.
    assert_eq!(cam.project(Vec3::new(0, 0, 3 * ONE / 2)).unwrap().1, 32767);
    assert!(z > 32767);
    assert_eq!(cam.project(Vec3::new(0, 0, 0)), None);
    assert_eq!(cam.project(Vec3::new(i32::MAX, 0, 1)), None);
}

/// Issue 12, item 2: the Q15 dot product overflowed `i64` on `i32::MIN`
/// components (a panic with overflow checks) and truncated results that do
/// not fit `i32` with `as` (`(2^25, 2^25, 0)` squared gave 0).
#[test]
fn issue_12_dot_overflow_and_truncation() {
    let big = Vec3::new(1 << 25, 1 << 25, 0);
    assert_eq!(big.dot(big), i32::MAX);
    assert_eq!(big.checked_dot(big), None);
    assert_eq!(big.dot(Vec3::new(-(1 << 25), 0, 0)), i32::MIN);
    let min = Vec3::new(i32::MIN, i32::MIN, i32::MIN);
    assert_eq!(min.dot(min), i32::MAX);
    assert_eq!(min.dot(Vec3::new(i32::MAX, i32::MAX, i32::MAX)), i32::MIN);
    // In range, exact: 3 * 2^44 / 2^15 = 3 * 2^29.
    let edge = Vec3::new(1 << 22, -(1 << 22), 1 << 22);
    assert_eq!(edge.checked_dot(edge), Some(3 << 29));
    // Rounding to nearest, ties up, on negative results too.
    assert_eq!(Vec3::new(1, 0, 0).dot(Vec3::new(-(1 << 14), 0, 0)), 0);
    assert_eq!(Vec3::new(1, 0, 0).dot(Vec3::new(-(1 << 14) - 1, 0, 0)), -1);
}

/// The rotated vector computed independently, exactly in `i128`, rounded
/// to nearest (ties up), not yet saturated.
fn reference_apply(r: &Rotation, v: Vec3) -> [i128; 3] {
    r.m.map(|row| {
        let d = i128::from(row[0]) * i128::from(v.x)
            + i128::from(row[1]) * i128::from(v.y)
            + i128::from(row[2]) * i128::from(v.z);
        (d + (1 << 14)).div_euclid(1 << 15)
    })
}

/// Issue 12, item 2: `Rotation::apply` wrapped around for large inputs
/// (`(i32::MAX, 0, i32::MAX)` turned by 45 degrees came out negative).
/// Within `±2^30` it is exact for every rotation `new` makes; beyond, it
/// saturates.
#[test]
fn issue_12_rotation_of_large_vectors() {
    let extremes = [i32::MIN, -(1 << 30), -1, 0, 1, 1 << 30, i32::MAX];
    let mut worst_row = 0i64;
    for yaw in (0..=u16::MAX).step_by(97) {
        for pitch in (0..=u16::MAX).step_by(89) {
            let r = Rotation::new(yaw, pitch);
            for row in r.m {
                let sum: i64 = row.iter().map(|&e| i64::from(e).abs()).sum();
                worst_row = worst_row.max(sum);
            }
            if yaw % 1067 != 0 || pitch % 979 != 0 {
                continue;
            }
            for &x in &extremes {
                for &y in &extremes {
                    for &z in &extremes {
                        let v = Vec3::new(x, y, z);
                        let want = reference_apply(&r, v);
                        let clamp = |w: i128| w.clamp(i32::MIN.into(), i32::MAX.into()) as i32;
                        let w = r.apply(v);
                        assert_eq!([w.x, w.y, w.z], want.map(clamp), "{yaw} {pitch} {v:?}");
                        let fits = want.iter().all(|&c| i32::try_from(c).is_ok());
                        assert_eq!(r.checked_apply(v).is_some(), fits, "{yaw} {pitch} {v:?}");
                        let small = [x, y, z].iter().all(|c| c.unsigned_abs() <= 1 << 30);
                        assert!(!small || fits, "{yaw} {pitch} {v:?} saturates");
                    }
                }
            }
        }
    }
    // The documented bound on a row's absolute sum: sqrt(3) ONE + 10.
    assert!(worst_row <= 56756 + 10, "{worst_row}");
    let r = Rotation::new(8192, 0);
    assert_eq!(r.apply(Vec3::new(i32::MAX, 0, i32::MAX)).x, i32::MAX);
}
