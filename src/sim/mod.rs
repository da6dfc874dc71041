//! The host simulator.
