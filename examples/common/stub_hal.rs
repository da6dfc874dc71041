//! Stand-ins for a board's SPI, I2C, pins and delay (embedded-hal 1.0),
//! so that the driver examples build and run without hardware: they
//! accept every transfer and count its bytes.

// Each example uses the stand-ins for its own bus.
#![allow(dead_code)]

use core::{cell::Cell, convert::Infallible};

use embedded_hal::{delay::DelayNs, digital, i2c, spi};

/// An SPI device that adds the bytes written to it to a counter.
#[derive(Debug)]
pub struct CountingSpi<'a>(pub &'a Cell<u32>);

impl spi::ErrorType for CountingSpi<'_> {
    type Error = Infallible;
}

impl spi::SpiDevice for CountingSpi<'_> {
    fn transaction(&mut self, operations: &mut [spi::Operation<'_, u8>]) -> Result<(), Infallible> {
        for op in operations {
            if let spi::Operation::Write(bytes) = op {
                self.0.set(self.0.get() + bytes.len() as u32);
            }
        }
        Ok(())
    }
}

/// An I2C bus that adds the bytes written to it to a counter.
#[derive(Debug)]
pub struct CountingI2c<'a>(pub &'a Cell<u32>);

impl i2c::ErrorType for CountingI2c<'_> {
    type Error = Infallible;
}

impl i2c::I2c for CountingI2c<'_> {
    fn transaction(
        &mut self,
        _address: u8,
        operations: &mut [i2c::Operation<'_>],
    ) -> Result<(), Infallible> {
        for op in operations {
            if let i2c::Operation::Write(bytes) = op {
                self.0.set(self.0.get() + bytes.len() as u32);
            }
        }
        Ok(())
    }
}

/// An output pin that goes nowhere.
#[derive(Debug, Default)]
pub struct NoPin;

impl digital::ErrorType for NoPin {
    type Error = Infallible;
}

impl digital::OutputPin for NoPin {
    fn set_low(&mut self) -> Result<(), Infallible> {
        Ok(())
    }

    fn set_high(&mut self) -> Result<(), Infallible> {
        Ok(())
    }
}

/// A delay that returns at once.
#[derive(Debug, Default)]
pub struct NoDelay;

impl DelayNs for NoDelay {
    fn delay_ns(&mut self, _ns: u32) {}
}
