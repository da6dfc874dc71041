//! How whole-byte pixels are written: spans filled with `memset`,
//! aligned or overlapping word stores and 16-byte blocks, lines walked
//! through the bytes, single pixels read and written. The formats in
//! [`bytes`](super::bytes) are built on these.

use core::ops::Range;

use crate::line::LinePixels;

/// [`PixelFormat::fill_line`](super::PixelFormat::fill_line) for `B`-byte
/// pixels, for the lines [`walks_by_index`] allows: the buffer as an array
/// of pixels, walked by index (one pixel along the major axis, one row or
/// pixel more along the minor axis where the line moves), one
/// bounds-checked store per pixel; a pixel past its row's end (which a
/// framebuffer's lines never have) lands in the next row.
///
/// Out of line: inlined beside the test of [`walks_by_index`], the walk
/// kept one of its steps on the stack and reloaded it every pixel
/// (Cortex-M4, `.ci/icount`: 200 px lines 2,170 → 2,336 instructions).
#[inline(never)]
pub(super) fn walk_line<const B: usize>(
    buffer: &mut [u8],
    stride: usize,
    pixels: &LinePixels,
    px: [u8; B],
) {
    walk_line_as(buffer, stride, pixels, px, halfword_cells());
}

/// Whether [`walk_line_as`] can walk `pixels` by index: rows of whole
/// pixels (`stride` a multiple of `B`), and an index that cannot leave
/// `isize` (it starts at the first pixel's and moves by at most a row and
/// a pixel a step), for a line with a pixel left (one iterated to its
/// end has none to walk). Always, for a framebuffer's own lines: their
/// pixels are inside it.
#[inline(always)]
pub(super) fn walks_by_index<const B: usize>(stride: usize, pixels: &LinePixels) -> bool {
    let first = pixels.first();
    let Ok(row) = u32::try_from(stride / B) else {
        return false;
    };
    let (x, y, steps) = (first.x.unsigned_abs(), first.y.unsigned_abs(), pixels.len());
    // Every term under 2^15 (a framebuffer's lines): the index stays under
    // 2^31 - 2^16, and no multiply is needed (a library call on ARMv6-M).
    // Not on 16-bit targets, whose `isize` is smaller.
    let small = |n: u32| n < 1 << 15;
    if steps == 0 {
        return false;
    }
    if usize::BITS >= 32 && small(row) && small(x) && small(y) && small(steps) {
        return stride.is_multiple_of(B);
    }
    // Exactly, in `u64`: the start is under 2^32 x 2^31 + 2^31.
    let start = u64::from(row) * u64::from(y) + u64::from(x);
    let reach = (u64::from(row) + 1).checked_mul(u64::from(steps));
    let end = reach.and_then(|reach| start.checked_add(reach));
    stride.is_multiple_of(B) && end.is_some_and(|n| isize::try_from(n).is_ok())
}

/// [`walk_line`], with 2-byte pixels walked as `u16` cells if `halves`
/// and the buffer is 2-byte aligned (the framebuffer's is word-aligned).
#[inline(always)]
fn walk_line_as<const B: usize>(
    buffer: &mut [u8],
    stride: usize,
    pixels: &LinePixels,
    px: [u8; B],
    halves: bool,
) {
    if let (true, &[a, b], Ok(cells)) = (
        halves,
        px.as_slice(),
        bytemuck::try_cast_slice_mut::<u8, u16>(buffer),
    ) {
        walk_cells(cells, stride / 2, pixels, u16::from_ne_bytes([a, b]));
        return;
    }
    walk_cells(buffer.as_chunks_mut::<B>().0, stride / B, pixels, px);
}

/// Whether 2-byte pixels are stored through a `u16` view of the bytes: on
/// 32-bit ARM cores without unaligned word stores (ARMv6-M), where a
/// `[u8; 2]` store is two `strb`, and a `u16` one `strh` (`.ci/icount` on
/// ARMv6-M: 1-pixel lines 200 px long 65,477 → 58,337 instructions for
/// the batch of 16, 16 px triangles 205,323 → 198,027 for 64). Cores
/// with them (`unaligned_words`) already store a `[u8; 2]` as one `strh`,
/// and their line walk took more instructions through the view
/// (Cortex-M4: those lines 34,719 → 39,663).
///
/// RISC-V and the other cores that are not hosts and have no
/// `unaligned_words` take the view too, as ARMv6-M does: their compilers
/// store a `[u8; 2]` byte by byte as well (RISC-V, `riscv32imc`: two `sb`).
#[inline(always)]
const fn halfword_cells() -> bool {
    !hosts_blocks() && !cfg!(unaligned_words)
}

/// Whether the target is a host whose cores store 16 unaligned bytes at
/// once (x86, x86-64, AArch64): spans are then filled with overlapping
/// 16-byte blocks ([`fill_overlapping`]). Elsewhere such a block is a
/// `memcpy` call or a store per byte: on RISC-V (`riscv32imc`, opt-level
/// "s") the framebuffer's `fill_span` of 2-byte pixels held five call
/// sites of `memcpy` and three of `copy_from_slice` through the blocks,
/// and now stores aligned halfwords and words, as ARMv6-M does
/// (`.ci/icount --target riscv32imc-unknown-none-elf`, the built-in
/// scene: 2,689,372 → 991,071 instructions at opt-level "s", 787,232 →
/// 605,983 at 3, though 16 px triangles went 1,343 → 1,611 there, where
/// the blocks were inlined; with [`fill_halves`] since, 973,448 and
/// 566,015, 16 px triangles 1,382 at opt-level 3).
#[inline(always)]
const fn hosts_blocks() -> bool {
    cfg!(any(
        target_arch = "x86",
        target_arch = "x86_64",
        target_arch = "aarch64"
    ))
}

/// [`walk_line`] over `cells`, one per pixel, `row` cells a row.
#[inline(always)]
fn walk_cells<T: Copy>(cells: &mut [T], row: usize, pixels: &LinePixels, px: T) {
    let first = pixels.first();
    let (Ok(x), Ok(y), Ok(row)) = (
        isize::try_from(first.x),
        isize::try_from(first.y),
        isize::try_from(row),
    ) else {
        return;
    };
    let Some(start) = y.checked_mul(row).and_then(|r| r.checked_add(x)) else {
        return;
    };
    let s = pixels.minor_step() as isize;
    let (major, minor) = if pixels.x_major() {
        (1, s * row)
    } else {
        (row, s)
    };
    pixels.walk(start, major, minor, move |at| {
        if let Some(cell) = usize::try_from(at).ok().and_then(|at| cells.get_mut(at)) {
            *cell = px;
        }
    });
}

/// The bytes of pixels `xs` in a row of `B`-byte pixels, if all are in
/// `row`.
#[inline]
pub(super) fn byte_span<const B: usize>(row: &mut [u8], xs: Range<usize>) -> Option<&mut [u8]> {
    row.get_mut(xs.start.checked_mul(B)?..xs.end.checked_mul(B)?)
}

/// Whether spans of `pixel` go as one `memset`: if all its bytes are equal
/// (black, white, any grey), and on other cores than hosts not for pixels
/// of 2 or 4 bytes. (On hosts, [`fill_bytes`] sends pixels of 2, 4 or 8
/// bytes to its blocks without asking.) On 32-bit ARM `memset` stores a word a
/// loop step, where the word paths store eight (`strd`) or a few
/// overlapping ones: spans and
/// rectangles of black took up to 2.8x the instructions of a colour's
/// (Cortex-M4, `.ci/icount` with black: the 240 px triangle 52,683
/// instructions through `memset`, 30,240 through the word path; 200 x 200
/// rectangles 1.67 instructions a pixel, 0.57 now, as any colour's). The
/// ARMv6-M build, counted on QEMU's Cortex-M3 board, gains too on all but
/// mid-sized triangles (in black: 240 px 60,414 → 49,640 instructions,
/// rectangles 200 x 200 67,581 → 34,428, but 64 px triangles 158,942 →
/// 168,347 for the batch of 15). Pixels of 3 bytes keep `memset` there:
/// their word path was not measured against it.
///
/// RISC-V likewise (`.ci/icount --target riscv32imc-unknown-none-elf`
/// with black): at opt-level 3, 16 px triangles 1,666 → 1,229
/// instructions, the 240 px one 49,670 → 35,841, 200 x 200 rectangles
/// 65,855 → 32,303; at opt-level "s", once [`fill_u32`] stored its blocks
/// without a loop, 2,452 → 1,906, 57,969 → 43,874 and 68,888 → 36,331.
/// Colours of unequal bytes gain too: the test of the bytes, made for
/// every span, is gone (opt-level 3: 4 px triangles 555 → 498).
#[inline(always)]
fn by_memset<const B: usize>(pixel: [u8; B]) -> bool {
    let words_faster = !hosts_blocks() && B > 1 && 4 % B == 0;
    !words_faster && pixel.iter().all(|&b| b == pixel[0])
}

/// Fills `bytes`, whole pixels, with copies of `pixel`.
///
/// On hosts ([`hosts_blocks`]), pixels of 2, 4 or 8 bytes as overlapping
/// 16-byte blocks ([`fill_overlapping`]: no pixel-by-pixel tail, measured
/// faster on x86-64 on spans of a few pixels to a few dozen), whatever
/// the colour. Otherwise, one `memset` if [`by_memset`], else:
///
/// - on a core that stores unaligned words (`unaligned_words`), for
///   pixels whose size divides 4, a few overlapping words, around aligned
///   runs of `strd` on long spans ([`fill_unaligned_words`]);
/// - on other cores (ARMv6-M, RISC-V, ...) and for spans of 16 pixels or
///   more, aligned 32-bit words of the repeating pattern ([`fill_words`]),
///   which the compiler turns into runs of `strd` on a Cortex-M4; shorter
///   spans there are a plain pixel loop (the aligned word setup costs
///   more than it saves), 2-byte pixels as halfwords
///   ([`halfword_cells`]);
/// - on hosts, pixels of other sizes by the pixel loop, which the
///   compiler vectorizes.
///
/// Hosts once sent a colour of equal bytes to `memset` before the blocks:
/// that test, made for every span, took 3 instructions a row on x86-64
/// (random triangles drawn by `draw_spans`, callgrind: tiny 485 a
/// triangle → 464, small 1,117 → 1,090, medium 3,709 → 3,590, large
/// 13,456 → 13,174, the mesh 999 → 977), and the blocks store as fast (a
/// 320 x 240 `Rgb565Le` clear, one span of 153,600 bytes, took 2.32 us in
/// black through `memset` and in red through the blocks, and takes 2.32
/// us in black through the blocks).
#[inline(always)]
pub(super) fn fill_bytes<const B: usize>(bytes: &mut [u8], pixel: [u8; B]) {
    let Some(&first) = pixel.first() else { return };
    if hosts_blocks() && 8 % B == 0 && B > 1 {
        fill_overlapping(bytes, pixel);
    } else if by_memset(pixel) {
        bytes.fill(first);
    } else if cfg!(unaligned_words) && 4 % B == 0 {
        fill_unaligned_words(bytes, pixel);
    } else if bytes.len() < 16 * B || hosts_blocks() {
        // Whole pixels only: `bytes` is a span of them. Hosts vectorize
        // this loop themselves, better than the word path below.
        fill_pixels(bytes, pixel);
    } else {
        fill_words(bytes, pixel);
    }
}

/// `bytes`, whole pixels, filled with `pixel` one pixel at a time; on
/// cores that are neither hosts nor `unaligned_words` Cortex-M cores
/// (ARMv6-M, RISC-V) 2-byte pixels as `u16` stores ([`halfword_cells`])
/// where the span is 2-byte aligned (always in the framebuffer, whose
/// buffer is word-aligned).
#[inline(always)]
fn fill_pixels<const B: usize>(bytes: &mut [u8], pixel: [u8; B]) {
    fill_pixels_as(bytes, pixel, halfword_cells());
}

/// [`fill_pixels`], with 2-byte pixels stored as `u16` if `halves` and
/// the span is 2-byte aligned.
#[inline(always)]
fn fill_pixels_as<const B: usize>(bytes: &mut [u8], pixel: [u8; B], halves: bool) {
    if let (true, &[a, b], Ok(halves)) = (
        halves,
        pixel.as_slice(),
        bytemuck::try_cast_slice_mut::<u8, u16>(bytes),
    ) {
        fill_halves(halves, u16::from_ne_bytes([a, b]));
        return;
    }
    bytes.as_chunks_mut::<B>().0.fill(pixel);
}

/// `halves.fill(half)`, with no loop for spans of 4 to 15 pixels: blocks
/// of four halfwords from both ends, overlapping in the middle (each
/// block written as four stores: at opt-level "s", a `[u16; 4]` array
/// store became a loop, and a loop over the blocks' offsets an array on
/// the stack).
///
/// Measured with `.ci/icount` against the plain `fill`: ARMv6-M, 16 px
/// triangles 3,109 → 2,967 instructions, the mesh 3,402 → 3,197, the
/// built-in scene 991,953 → 963,321, 4 px triangles level (1,691 →
/// 1,689); RISC-V (`riscv32imc`, opt-level 3), 16 px triangles 1,611 →
/// 1,382, the scene 605,983 → 566,015, but 4 px triangles 495 → 555; at
/// opt-level "s", 16 px 2,236 → 2,098, the scene 991,071 → 973,448, 4 px
/// 922 → 956. Spans of one to three pixels keep the loop: three stores
/// (first, middle, last) took 16 px triangles to 1,212 on RISC-V but 3 px
/// lines from 8,163 to 9,065.
#[inline(always)]
fn fill_halves(halves: &mut [u16], half: u16) {
    let n = halves.len();
    let mut put = |at: usize| {
        if let Some([a, b, c, d]) = halves.get_mut(at..at + 4) {
            (*a, *b, *c, *d) = (half, half, half, half);
        }
    };
    if n < 4 {
        halves.fill(half);
    } else if n < 8 {
        put(0);
        put(n - 4);
    } else if n < 16 {
        put(0);
        put(4);
        put(n - 8);
        put(n - 4);
    } else {
        halves.fill(half);
    }
}

/// [`fill_bytes`] on hosts, for pixels whose size divides 8: 16-byte
/// blocks of the repeating pattern, the last one moved back to end where
/// the span ends (overlapping the one before it, and still starting on a
/// pixel), a span of up to 64 bytes as two or four such blocks from its
/// two ends, a span under 16 bytes as two overlapping 8- or 4-byte
/// blocks, and a single pixel as one store. No pixel-by-pixel tail, and
/// the same few branches for spans of any length.
#[inline(always)]
fn fill_overlapping<const B: usize>(bytes: &mut [u8], pixel: [u8; B]) {
    let pattern: [u8; 16] = core::array::from_fn(|i| pixel[i % B]);
    let n = bytes.len();
    // Each block starts a whole number of pixels into the span (B divides
    // 8, and `n` is whole pixels): the pattern lines up. Blocks are whole
    // arrays, one 16-byte store each on x86-64 (a block copied from a
    // slice went as two 8-byte stores, and the last one as an 8-byte
    // store and four 2-byte ones). Long spans are tested first: testing
    // the short ones first saved instructions on the small triangles'
    // rows (callgrind, small 1,090 a triangle → 1,074, tiny 464 → 460)
    // but took more time on the longer ones (`pools_ab.py`, 9 runs with
    // loops aligned to 64 bytes: `draw_spans` medium 1.10x, large 1.05x
    // and the mesh 1.08x the time).
    if n > 64 {
        let (blocks, rest) = bytes.as_chunks_mut::<16>();
        blocks.fill(pattern);
        if !rest.is_empty() {
            if let Some(last) = bytes.last_chunk_mut::<16>() {
                *last = pattern;
            }
        }
    } else if n >= 16 {
        // Up to 64 bytes: the first and the last block, and if needed the
        // second and the one before the last, overlapping. No loop: the
        // loop's set-up and its remainder took about 20 instructions a row
        // on spans of a few blocks (random medium triangles, callgrind,
        // with the sink inlined into the row loop by attribute as it is
        // now: 5,264 instructions a triangle through the loop, 4,482 so).
        if let Some(first) = bytes.first_chunk_mut::<16>() {
            *first = pattern;
        }
        if let Some(last) = bytes.last_chunk_mut::<16>() {
            *last = pattern;
        }
        if n > 32 {
            if let Some(Ok(b)) = bytes.get_mut(16..32).map(<&mut [u8; 16]>::try_from) {
                *b = pattern;
            }
            if let Some(Ok(b)) = bytes.get_mut(n - 32..n - 16).map(<&mut [u8; 16]>::try_from) {
                *b = pattern;
            }
        }
    } else if n >= 8 {
        overlapping_pair(bytes, &pattern[..8]);
    } else if n >= 4 && 4 % B == 0 {
        overlapping_pair(bytes, &pattern[..4]);
    } else if B == 1 {
        // Two or three 1-byte pixels (the framebuffer sends those to
        // `memset`; this keeps the function whole for any `B`).
        bytes.fill(pixel[0]);
    } else if let Some(only) = bytes.first_chunk_mut::<B>() {
        // One pixel: what is left of whole pixels of 2, 4 or 8 bytes under
        // 8 bytes, or under 4 when `B` divides 4 (`n` is 0 or `B`). One
        // store, not the loop's set-up for it (x86-64, random triangles
        // drawn by `draw_spans`, instructions counted by callgrind: tiny
        // 533 a triangle → 526, small 1,229 → 1,220, the mesh 1,101 →
        // 1,090). And no pixel loop at all after it: the row loop that
        // inlines this then stopped stepping that loop's row address, 2
        // instructions a row (tiny 530 → 515, small 1,180 → 1,127, medium
        // 3,857 → 3,719, large 13,789 → 13,466, the mesh 1,056 → 1,009).
        *only = pixel;
    }
}

/// Calls `$put` at each offset: as a loop over an array of them, or,
/// in builds optimized for size (`optimize_for_size`: opt-level "s" or
/// "z", set by the build script), as one written-out call each, because
/// at "s" the array stays an array on the stack and the loop a loop.
///
/// The Cortex-M4 (`.ci/icount`) at opt-level "s", loop → calls: 16 px
/// triangles 2,335 → 1,601 instructions each, the 240 px one 49,081 →
/// 31,496, 8 px wide, 100 px long lines 16,942 → 10,062 each, the built-in scene
/// 797,083 → 602,969; rectangles of 64 x 64 and 200 x 200 0.6 % to 1 %
/// more; and 188 bytes less flash for flat triangles (4,812 → 4,624). At
/// opt-level 3 the calls cost instead (16 px 1,247 → 1,296, 240 px 25,103
/// → 26,031, the scene 480,487 → 492,226, when tried unconditionally: the
/// row loop's registers fell out differently), so other builds keep the
/// loop.
macro_rules! put_each {
    ($put:ident: $($at:expr),+) => {
        #[cfg(optimize_for_size)]
        {
            $($put($at);)+
        }
        #[cfg(not(optimize_for_size))]
        for at in [$($at),+] {
            $put(at);
        }
    };
}

/// [`fill_bytes`] on a Cortex-M3, M4, M7 or M33 (the build script's
/// `unaligned_words`: ARMv7-M and ARMv8-M Mainline cores store a 32-bit
/// word at any address, unless a program sets the trap for it), for a
/// pixel size that divides 4: spans under 8 bytes as pixels, shorter
/// ones than 32 bytes as four or eight 32-bit words at the span's start
/// and back from its end, overlapping in the middle (each starts a whole
/// number of pixels in, so the pattern lines up), and longer ones as
/// aligned blocks of eight words (runs of `strd`) between one word at
/// the start and eight back from the end, which cover whatever the
/// blocks leave at either end (under 4 bytes before the first block,
/// under 32 after the last). No loop for short spans, and no head or
/// tail loop for long ones.
///
/// On a Cortex-M4 (`.ci/icount`, when it came), the short spans' words
/// took 16 px triangles from 1,476 instructions with the pixel loop to
/// 1,349, the mesh from 1,914 to 1,728 and the built-in scene from
/// 601,066 to 576,187, for 1,476 bytes more flash in the whole firmware
/// (at "s"); with words from 4 bytes on, 4 px triangles took 725 to 733
/// instructions (679 with the pixel loop under 8). ARMv6-M, which has no
/// unaligned stores, keeps the pixel loop and [`fill_words`].
#[inline(always)]
fn fill_unaligned_words<const B: usize>(bytes: &mut [u8], pixel: [u8; B]) {
    // The pixel repeated over a word: for 2-byte pixels the pixel's
    // `u16` times 0x1_0001, one shifted `orr` on a Cortex-M (built byte by
    // byte, it took four instructions a span).
    let word = match pixel.as_slice() {
        &[a, b] => (u32::from(u16::from_ne_bytes([a, b])) * 0x1_0001).to_ne_bytes(),
        _ => core::array::from_fn(|i| pixel[i % B]),
    };
    let n = bytes.len();
    if n < 8 {
        bytes.as_chunks_mut::<B>().0.fill(pixel);
        return;
    }
    if n >= 32 {
        let (head, words, _) = bytemuck::pod_align_to_mut::<u8, u32>(bytes);
        // The first aligned word is span byte `head.len()` on: the pattern
        // turned by that many bytes (by whole pixels, in the framebuffer).
        let turn = 8 * (head.len() as u32 % 4);
        let aligned = match cfg!(target_endian = "little") {
            true => u32::from_ne_bytes(word).rotate_right(turn),
            false => u32::from_ne_bytes(word).rotate_left(turn),
        };
        fill_blocks(words.as_chunks_mut::<8>().0, aligned);
    }
    // The word at byte `at`, if it lies in the span.
    let mut put = |at: usize| {
        if let Some(Ok(w)) = bytes.get_mut(at..at + 4).map(<&mut [u8; 4]>::try_from) {
            *w = word;
        }
    };
    if n >= 32 {
        put(0);
        put_each!(put: n - 32, n - 28, n - 24, n - 20, n - 16, n - 12, n - 8, n - 4);
    } else if n >= 16 {
        put_each!(put: 0, 4, 8, 12, n - 16, n - 12, n - 8, n - 4);
    } else {
        put_each!(put: 0, 4, n - 8, n - 4);
    }
}

/// Writes `block` at the start and at the end of `bytes` (`k <=
/// bytes.len() <= 2 k` for a block of `k` bytes: together they cover it).
#[inline(always)]
fn overlapping_pair(bytes: &mut [u8], block: &[u8]) {
    let n = bytes.len();
    if let Some(head) = bytes.get_mut(..block.len()) {
        head.copy_from_slice(block);
    }
    if let Some(tail) = n
        .checked_sub(block.len())
        .and_then(|at| bytes.get_mut(at..))
    {
        tail.copy_from_slice(block);
    }
}

/// [`fill_bytes`] through aligned words.
#[inline]
fn fill_words<const B: usize>(bytes: &mut [u8], pixel: [u8; B]) {
    // Byte `i` of the span is byte `i % B` of the pixel.
    let at = |i: usize| pixel[i % B];
    let (head, words, tail) = bytemuck::pod_align_to_mut::<u8, u32>(bytes);
    let offset = head.len();
    if offset % B == 0 && 4 % B == 0 {
        // Whole pixels up to the boundary (for 2-byte pixels in a
        // word-aligned buffer: none or one), then one repeated word.
        for px in head.as_chunks_mut::<B>().0 {
            *px = pixel;
        }
        fill_u32(words, u32::from_ne_bytes([at(0), at(1), at(2), at(3)]));
        // The tail is whole pixels too: the span and the head are.
        for px in tail.as_chunks_mut::<B>().0 {
            *px = pixel;
        }
        return;
    }
    for (i, b) in head.iter_mut().enumerate() {
        *b = at(i);
    }
    // Four pixels are B whole words; this block starts where `words` does.
    let mut block = [0u32; B];
    for (k, w) in block.iter_mut().enumerate() {
        let i = offset + 4 * k;
        *w = u32::from_ne_bytes([at(i), at(i + 1), at(i + 2), at(i + 3)]);
    }
    let (blocks, rest) = words.as_chunks_mut::<B>();
    for chunk in blocks {
        *chunk = block;
    }
    for (w, b) in rest.iter_mut().zip(block) {
        *w = b;
    }
    let offset = offset + 4 * words.len();
    for (i, b) in tail.iter_mut().enumerate() {
        *b = at(offset + i);
    }
}

/// [`fill_bytes`] on the same pixels `xs` of many rows, each row one
/// call's worth of checks and stores: where [`fill_bytes`] would take the
/// word path, the split of the span into pixels before the first word
/// boundary, whole words and pixels after the last one is worked out once
/// (rows starting on a word boundary split alike), and a row that does
/// not start on one is filled by [`fill_bytes`].
#[inline(always)]
pub(super) fn fill_rows_bytes<'a, const B: usize>(
    rows: impl Iterator<Item = &'a mut [u8]>,
    xs: Range<usize>,
    pixel: [u8; B],
) {
    let (Some(lo), Some(hi)) = (xs.start.checked_mul(B), xs.end.checked_mul(B)) else {
        return;
    };
    if hosts_blocks() || by_memset(pixel) || xs.len() < 16 || 4 % B != 0 {
        for row in rows {
            if let Some(bytes) = row.get_mut(lo..hi) {
                fill_bytes(bytes, pixel);
            }
        }
        return;
    }
    fill_rows_words(rows, lo..hi, pixel);
}

/// The word path of [`fill_rows_bytes`], bytes `lo..hi` of each row (`B`
/// divides 4, `hi - lo >= 4 B`).
#[inline(always)]
fn fill_rows_words<'a, const B: usize>(
    rows: impl Iterator<Item = &'a mut [u8]>,
    Range { start: lo, end: hi }: Range<usize>,
    pixel: [u8; B],
) {
    // B divides 4, so word boundaries fall between pixels and every word
    // holds the pattern starting with byte 0 of a pixel. 4 pixels or more
    // hold a whole word: `lo <= first <= last <= hi`.
    let word = u32::from_ne_bytes(core::array::from_fn(|i| pixel[i % B]));
    let (first, last) = (lo.next_multiple_of(4), hi / 4 * 4);
    if first > last {
        return;
    }
    for row in rows {
        let Some(row) = row.get_mut(..hi) else {
            continue;
        };
        let (front, back) = row.split_at_mut(last);
        let (front, middle) = front.split_at_mut(first);
        match bytemuck::try_cast_slice_mut::<u8, u32>(middle) {
            Ok(words) => {
                for px in front
                    .get_mut(lo..)
                    .unwrap_or_default()
                    .as_chunks_mut::<B>()
                    .0
                {
                    *px = pixel;
                }
                fill_u32(words, word);
                for px in back.as_chunks_mut::<B>().0 {
                    *px = pixel;
                }
            }
            Err(_) => fill_bytes(row.get_mut(lo..).unwrap_or_default(), pixel),
        }
    }
}

/// `words.fill(word)`, 8 words (32 bytes) a step: on a Cortex-M4 each
/// step is a few multi-register stores (`strd`/`stm`) and one loop test,
/// about 0.4 instructions per 2-byte pixel, where a plain `fill` is
/// unrolled only 4 times.
///
/// The eight stores are written out: as one `[u32; 8]` array store, at
/// opt-level "s" RISC-V made it a loop of a store and two other
/// instructions a word (`.ci/icount --target riscv32imc-unknown-none-elf`
/// at "s": the 240 px triangle in black 70,928 → 43,874 instructions,
/// the built-in scene 925,339 → 717,518). At opt-level 3 both forms
/// count the same, on RISC-V and on both Cortex-M builds (the built-in
/// scene on the Cortex-M4 within 100 instructions, as code moved).
#[inline(always)]
fn fill_u32(words: &mut [u32], word: u32) {
    let (blocks, rest) = words.as_chunks_mut::<8>();
    fill_blocks(blocks, word);
    rest.fill(word);
}

/// Every word of `blocks` set to `word`, a block's eight stores written
/// out (see [`fill_u32`]).
#[inline(always)]
fn fill_blocks(blocks: &mut [[u32; 8]], word: u32) {
    for [a, b, c, d, e, f, g, h] in blocks {
        (*a, *b, *c, *d, *e, *f, *g, *h) = (word, word, word, word, word, word, word, word);
    }
}

/// [`PixelFormat::write_span`](super::PixelFormat::write_span) for `B`-byte pixels.
pub(super) fn write_bytes<const B: usize, C, I: Iterator<Item = C>>(
    row: &mut [u8],
    xs: Range<usize>,
    colors: I,
    encode: impl Fn(C) -> [u8; B],
) -> usize {
    let Some(bytes) = byte_span::<B>(row, xs) else {
        return 0;
    };
    let mut written = 0;
    for (px, color) in bytes.as_chunks_mut::<B>().0.iter_mut().zip(colors) {
        *px = encode(color);
        written += 1;
    }
    written
}

/// The bytes of pixel `x` in a row of `B`-byte pixels.
pub(super) fn read_bytes<const B: usize>(row: &[u8], x: usize) -> Option<[u8; B]> {
    let start = x.checked_mul(B)?;
    row.get(start..start.checked_add(B)?)?.try_into().ok()
}

#[cfg(test)]
mod tests {
    use embedded_graphics_core::geometry::Point;

    use super::*;

    /// The plain fill the word and block paths must equal: byte `i` of
    /// the span is byte `i % B` of the pixel.
    fn plain<const B: usize>(bytes: &mut [u8], pixel: [u8; B]) {
        for (i, b) in bytes.iter_mut().enumerate() {
            *b = pixel[i % B];
        }
    }

    /// Every start and length within a few words, in a buffer whose rows
    /// start on and off word boundaries.
    fn check<const B: usize>(pixel: [u8; B]) {
        #[repr(C, align(4))]
        struct Words([u8; 640]);
        for offset in 0..4 {
            for x0 in 0..12 {
                for len in 0..40 {
                    let (lo, hi) = (B * x0, B * (x0 + len));
                    let (mut want, mut got) = (Words([0; 640]), Words([0; 640]));
                    plain(&mut want.0[offset + lo..offset + hi], pixel);
                    if 8 % B == 0 {
                        fill_overlapping(&mut got.0[offset + lo..offset + hi], pixel);
                        assert_eq!(want.0, got.0, "fill_overlapping {offset} {x0} {len}");
                    }
                    if 4 % B == 0 {
                        let mut got = Words([0; 640]);
                        fill_unaligned_words(&mut got.0[offset + lo..offset + hi], pixel);
                        assert_eq!(want.0, got.0, "fill_unaligned_words {offset} {x0} {len}");
                    }
                    for halves in [false, true] {
                        let mut got = Words([0; 640]);
                        fill_pixels_as(&mut got.0[offset + lo..offset + hi], pixel, halves);
                        assert_eq!(want.0, got.0, "fill_pixels {halves} {offset} {x0} {len}");
                    }
                    if len < 4 {
                        // Under the word paths' four pixels.
                        continue;
                    }
                    let mut got = Words([0; 640]);
                    fill_words(&mut got.0[offset + lo..offset + hi], pixel);
                    assert_eq!(want.0, got.0, "fill_words {offset} {x0} {len}");
                    if 4 % B == 0 {
                        // Three rows of 208 bytes.
                        let mut want = Words([0; 640]);
                        let rows = want.0[offset..offset + 624].chunks_exact_mut(208);
                        rows.for_each(|row| plain(&mut row[lo..hi], pixel));
                        let mut got = Words([0; 640]);
                        let rows = got.0[offset..offset + 624].chunks_exact_mut(208);
                        fill_rows_words(rows, lo..hi, pixel);
                        assert_eq!(want.0, got.0, "fill_rows_words {offset} {x0} {len}");
                    }
                }
            }
        }
    }

    /// Lines walked through `u16` cells (as on ARMv6-M) light the bytes
    /// the pixel walk lights, in a buffer on and off a 2-byte boundary
    /// (off it, the walk falls back to pixels): lines from every pixel of
    /// a 9 x 7 grid to every other, drawn into a 12 x 8 screen.
    #[test]
    fn lines_through_halfword_cells_equal_the_pixel_walk() {
        use embedded_graphics_core::{geometry::Size, primitives::Rectangle};

        #[repr(C, align(4))]
        struct Words([u8; 200]);
        let screen = Rectangle::new(Point::zero(), Size::new(12, 8));
        let grid = (-1..8).flat_map(|x| (-1..6).map(move |y| Point::new(x * 2, y * 2 - 1)));
        let mut lines = 0;
        for a in grid.clone() {
            for b in grid.clone() {
                let Some(pixels) = crate::line::Line::new(a, b).pixels(&screen) else {
                    continue;
                };
                for offset in [0, 1] {
                    let (mut want, mut got) = (Words([0; 200]), Words([0; 200]));
                    let span = offset..offset + 192;
                    walk_line_as(&mut want.0[span.clone()], 24, &pixels, [1, 2], false);
                    walk_line_as(&mut got.0[span], 24, &pixels, [1, 2], true);
                    assert_eq!(want.0, got.0, "{a:?} {b:?} at {offset}");
                }
                lines += 1;
            }
        }
        assert!(lines > 3000, "{lines}");
    }

    #[test]
    fn word_and_block_paths_equal_the_plain_fill() {
        check([7]);
        check([1, 2]);
        check([1, 2, 3]);
        check([1, 2, 3, 4]);
    }
}
