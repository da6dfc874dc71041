//! Owned, const-sized framebuffers.
