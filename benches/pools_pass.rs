//! One contender's passes over one random pool of `benches/pools.rs`,
//! for counting their instructions under callgrind
//! (`benches/pools_callgrind.py`): counts do not drift with the machine
//! as times do, so a change to the fill shows in them exactly.
//!
//! `pools_pass POOL CONTENDER PASSES` runs `PASSES` passes of the named
//! contender (`limit`, `draw_spans`, ...) over pool number `POOL` (0 to
//! 4, in the order of `benches/pools.rs`) and prints the pool's name and
//! number of triangles; with no arguments (as `cargo
//! test --all-targets` runs it), one pass of every contender over every
//! pool, as a smoke test.

#[path = "common/pools.rs"]
mod pools;
use pools::{contenders, Prepared, Targets, POOLS};

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    if args.is_empty() {
        for (_, pool) in POOLS {
            let pool = Prepared::new(&pool());
            let mut targets = Targets::new();
            for (_, pass) in contenders(&pool, &mut targets).iter_mut() {
                pass();
            }
        }
        println!("Smoke test: one pass of each contender over each pool.");
        return;
    }
    let [pool, name, passes] = &args[..] else {
        panic!("usage: pools_pass POOL CONTENDER PASSES");
    };
    let (pool_name, generate) = POOLS[pool.parse::<usize>().expect("a pool number")];
    let pool = Prepared::new(&generate());
    // For the counting script: the pool's name and size.
    println!("pool\t{pool_name}\t{}", pool.tris.len());
    let mut targets = Targets::new();
    let mut all = contenders(&pool, &mut targets);
    let (_, pass) = all
        .iter_mut()
        .find(|(n, _)| n == name)
        .unwrap_or_else(|| panic!("no contender {name}"));
    for _ in 0..passes.parse::<u32>().expect("a number of passes") {
        pass();
    }
}
