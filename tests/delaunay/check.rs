//! An independent checker for Delaunay triangulations, written apart from
//! the library: its own convex hull, its own exact arithmetic (`i128` with
//! checked operations, falling back to a small signed bignum), and the
//! definitions taken literally.

use std::collections::{BTreeMap, BTreeSet};

/// A point in raw 20.12 units.
pub type Pt = (i64, i64);

/// A signed integer of any size: sign and base-2^32 magnitude, little end
/// first, no leading zero limbs.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Big {
    negative: bool,
    limbs: Vec<u64>,
}

impl Big {
    fn from_i128(v: i128) -> Self {
        let mut m = v.unsigned_abs();
        let mut limbs = vec![];
        while m > 0 {
            limbs.push((m & 0xFFFF_FFFF) as u64);
            m >>= 32;
        }
        Big {
            negative: v < 0,
            limbs,
        }
    }

    fn trim(mut self) -> Self {
        while self.limbs.last() == Some(&0) {
            self.limbs.pop();
        }
        if self.limbs.is_empty() {
            self.negative = false;
        }
        self
    }

    fn mul(&self, o: &Big) -> Big {
        let mut out = vec![0u64; self.limbs.len() + o.limbs.len() + 1];
        for (i, &a) in self.limbs.iter().enumerate() {
            let mut carry = 0u64;
            for (j, &b) in o.limbs.iter().enumerate() {
                let t = out[i + j] + a * b + carry;
                out[i + j] = t & 0xFFFF_FFFF;
                carry = t >> 32;
            }
            out[i + o.limbs.len()] += carry;
        }
        Big {
            negative: self.negative != o.negative,
            limbs: out,
        }
        .trim()
    }

    fn cmp_magnitude(a: &[u64], b: &[u64]) -> std::cmp::Ordering {
        a.len()
            .cmp(&b.len())
            .then_with(|| a.iter().rev().cmp(b.iter().rev()))
    }

    fn add(&self, o: &Big) -> Big {
        if self.negative == o.negative {
            let n = self.limbs.len().max(o.limbs.len()) + 1;
            let mut out = vec![0u64; n];
            let mut carry = 0;
            for (k, slot) in out.iter_mut().enumerate() {
                let t = self.limbs.get(k).unwrap_or(&0) + o.limbs.get(k).unwrap_or(&0) + carry;
                *slot = t & 0xFFFF_FFFF;
                carry = t >> 32;
            }
            return Big {
                negative: self.negative,
                limbs: out,
            }
            .trim();
        }
        // Different signs: the larger magnitude minus the smaller.
        let (big, small) = match Self::cmp_magnitude(&self.limbs, &o.limbs) {
            std::cmp::Ordering::Less => (o, self),
            _ => (self, o),
        };
        let mut out = vec![0u64; big.limbs.len()];
        let mut borrow = 0u64;
        for (k, slot) in out.iter_mut().enumerate() {
            let sub = small.limbs.get(k).unwrap_or(&0) + borrow;
            let a = big.limbs[k];
            (*slot, borrow) = if a >= sub {
                (a - sub, 0)
            } else {
                (a + (1 << 32) - sub, 1)
            };
        }
        Big {
            negative: big.negative,
            limbs: out,
        }
        .trim()
    }

    fn signum(&self) -> i32 {
        match (self.limbs.is_empty(), self.negative) {
            (true, _) => 0,
            (false, true) => -1,
            (false, false) => 1,
        }
    }
}

/// `(b - a) x (c - a)`: positive for the library's orientation.
pub fn cross(a: Pt, b: Pt, c: Pt) -> i128 {
    let d = |p: Pt, q: Pt| (i128::from(q.0 - p.0), i128::from(q.1 - p.1));
    let ((ux, uy), (vx, vy)) = (d(a, b), d(a, c));
    ux * vy - uy * vx
}

/// Sign of the in-circle determinant of `d` against `a, b, c` (positive:
/// strictly inside for `cross(a, b, c) > 0`), as the 4 x 4 determinant with
/// rows `(x, y, x² + y², 1)` expanded along the last column, in `i128` when
/// no operation overflows and in `Big` otherwise.
pub fn in_circle_sign(a: Pt, b: Pt, c: Pt, d: Pt) -> i32 {
    // Relative to d, the 4 x 4 determinant becomes a 3 x 3 one.
    let rows: Vec<[i128; 3]> = [a, b, c]
        .iter()
        .map(|p| {
            let (x, y) = (i128::from(p.0 - d.0), i128::from(p.1 - d.1));
            [x, y, x * x + y * y]
        })
        .collect();
    let checked = || -> Option<i128> {
        let minor = |r: usize, s: usize| {
            rows[r][1]
                .checked_mul(rows[s][2])?
                .checked_sub(rows[r][2].checked_mul(rows[s][1])?)
        };
        // Expansion along the first column.
        let t0 = rows[0][0].checked_mul(minor(1, 2)?)?;
        let t1 = rows[1][0].checked_mul(minor(0, 2)?)?;
        let t2 = rows[2][0].checked_mul(minor(0, 1)?)?;
        t0.checked_sub(t1)?.checked_add(t2)
    };
    if let Some(v) = checked() {
        return v.signum() as i32;
    }
    let b = |v: i128| Big::from_i128(v);
    let neg = |v: Big| {
        Big {
            negative: !v.negative,
            ..v
        }
        .trim()
    };
    let minor = |r: usize, s: usize| {
        b(rows[r][1])
            .mul(&b(rows[s][2]))
            .add(&neg(b(rows[r][2]).mul(&b(rows[s][1]))))
    };
    let t0 = b(rows[0][0]).mul(&minor(1, 2));
    let t1 = b(rows[1][0]).mul(&minor(0, 2));
    let t2 = b(rows[2][0]).mul(&minor(0, 1));
    t0.add(&neg(t1)).add(&t2).signum()
}

/// The convex hull's boundary points in order (positive orientation),
/// including points in the middle of its sides: Andrew's monotone chain
/// keeping collinear points. Needs three points not on one line.
pub fn hull(points: &BTreeSet<Pt>) -> Vec<Pt> {
    let sorted: Vec<Pt> = points.iter().copied().collect();
    let chain = |pts: &mut dyn Iterator<Item = Pt>| {
        let mut h: Vec<Pt> = vec![];
        for p in pts {
            while h.len() >= 2 && cross(h[h.len() - 2], h[h.len() - 1], p) < 0 {
                h.pop();
            }
            h.push(p);
        }
        h.pop();
        h
    };
    let mut h = chain(&mut sorted.iter().copied());
    h.extend(chain(&mut sorted.iter().rev().copied()));
    h
}

/// Whether every point of the set lies on one line.
pub fn all_collinear(points: &BTreeSet<Pt>) -> bool {
    let v: Vec<Pt> = points.iter().copied().collect();
    v.len() < 3 || v[2..].iter().all(|&p| cross(v[0], v[1], p) == 0)
}

/// Checks that `triangles` is a Delaunay triangulation of `points` (all
/// input points, duplicates allowed); panics with the reason if not.
/// Returns the hull (empty for fewer than 3 points or a collinear set).
pub fn check(points: &[Pt], triangles: &[[Pt; 3]]) -> Vec<Pt> {
    let set: BTreeSet<Pt> = points.iter().copied().collect();
    if all_collinear(&set) {
        assert!(
            triangles.is_empty(),
            "collinear or < 3 points gave {} triangles",
            triangles.len()
        );
        return vec![];
    }
    let mut used = BTreeSet::new();
    // Net count of each directed edge: +1 for u -> v, -1 for v -> u.
    let mut net: BTreeMap<(Pt, Pt), i32> = BTreeMap::new();
    let mut directed = BTreeSet::new();
    for t in triangles {
        let area = cross(t[0], t[1], t[2]);
        assert!(area != 0, "zero-area triangle {t:?}");
        let [a, b, c] = if area > 0 { *t } else { [t[0], t[2], t[1]] };
        for (u, v) in [(a, b), (b, c), (c, a)] {
            assert!(
                set.contains(&u),
                "triangle vertex {u:?} is not an input point"
            );
            used.insert(u);
            assert!(
                directed.insert((u, v)),
                "edge {u:?} -> {v:?} in two triangles: overlap"
            );
            *net.entry((u.min(v), u.max(v))).or_default() += if u < v { 1 } else { -1 };
        }
    }
    assert_eq!(used.len(), set.len(), "not every input point is a vertex");
    let h = hull(&set);
    let mut boundary = BTreeMap::new();
    for k in 0..h.len() {
        let (u, v) = (h[k], h[(k + 1) % h.len()]);
        boundary.insert((u.min(v), u.max(v)), if u < v { 1 } else { -1 });
    }
    // The triangles' boundary chain equals the hull's: with every triangle
    // positive, each point of the hull is covered exactly once.
    for (edge, &n) in &net {
        let want = boundary.get(edge).copied().unwrap_or(0);
        assert_eq!(
            n, want,
            "edge {edge:?}: net count {n}, the hull says {want}"
        );
    }
    for edge in boundary.keys() {
        assert!(
            net.contains_key(edge),
            "hull edge {edge:?} is in no triangle"
        );
    }
    let n = set.len();
    assert_eq!(
        triangles.len(),
        2 * n - h.len() - 2,
        "triangle count for n = {n}, h = {}",
        h.len()
    );
    if set.len() * triangles.len() <= 4_000_000 {
        check_empty_circles(&set, triangles);
    } else {
        check_locally_delaunay(triangles);
    }
    h
}

/// No point lies strictly inside any triangle's circumcircle.
pub fn check_empty_circles(set: &BTreeSet<Pt>, triangles: &[[Pt; 3]]) {
    for t in triangles {
        let [a, b, c] = if cross(t[0], t[1], t[2]) > 0 {
            *t
        } else {
            [t[0], t[2], t[1]]
        };
        for &p in set {
            assert!(
                in_circle_sign(a, b, c, p) <= 0,
                "{p:?} strictly inside the circumcircle of {t:?}"
            );
        }
    }
}

/// For each edge shared by two triangles, neither far vertex lies strictly
/// inside the other triangle's circumcircle. For a triangulation (checked
/// above) this is equivalent to empty circumcircles (Delaunay's lemma), and
/// takes time linear in the triangles rather than quadratic.
pub fn check_locally_delaunay(triangles: &[[Pt; 3]]) {
    let mut far: BTreeMap<(Pt, Pt), Pt> = BTreeMap::new();
    for t in triangles {
        let [a, b, c] = if cross(t[0], t[1], t[2]) > 0 {
            *t
        } else {
            [t[0], t[2], t[1]]
        };
        for (u, v, w) in [(a, b, c), (b, c, a), (c, a, b)] {
            // The triangle across u -> v has it as v -> u.
            if let Some(&d) = far.get(&(v, u)) {
                assert!(
                    in_circle_sign(a, b, c, d) <= 0,
                    "{d:?} strictly inside the circumcircle of {t:?}"
                );
                assert!(
                    in_circle_sign(v, u, d, w) <= 0,
                    "{w:?} strictly inside the circumcircle of {:?}",
                    (v, u, d)
                );
            }
            far.insert((u, v), w);
        }
    }
}

#[test]
fn bignum_agrees_with_i128() {
    let vals = [
        0i128,
        1,
        -1,
        12345678901234567,
        -(1 << 90) + 17,
        (1 << 62) - 3,
        -99,
    ];
    for &x in &vals {
        for &y in &vals {
            let (bx, by) = (Big::from_i128(x), Big::from_i128(y));
            assert_eq!(bx.add(&by), Big::from_i128(x + y), "{x} + {y}");
            if let Some(p) = x.checked_mul(y) {
                assert_eq!(bx.mul(&by), Big::from_i128(p), "{x} * {y}");
            }
        }
    }
}

#[test]
fn checker_in_circle_at_the_range_extremes() {
    let m = i64::from(i32::MAX);
    let n = i64::from(i32::MIN);
    // Four corners of the whole range: a rectangle, so cocircular.
    assert_eq!(in_circle_sign((n, n), (m, n), (m, m), (n, m)), 0);
    assert_eq!(in_circle_sign((n, n), (m, n), (m, m), (0, 0)), 1);
    assert_eq!(in_circle_sign((n, n), (m, n), (0, 1), (0, m)), -1);
}
