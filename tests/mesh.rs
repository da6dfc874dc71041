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
