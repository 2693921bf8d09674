//! CPU cycles of this process as a criterion measurement, read from the Linux perf counter.
//!
//! On a shared machine the wall time of the same benchmark moves by 10–30 % from run to run,
//! because other work takes the processor away in bursts; the cycles this process spends
//! while it runs move far less, so ratios between variants read from cycles are steadier.

use criterion::Throughput;
use criterion::measurement::{Measurement, ValueFormatter};
use perf_event::events::Hardware;
use perf_event::{Builder, Counter};
use std::cell::RefCell;

/// The cycle counter, opened and enabled once.
pub struct Cycles {
    counter: RefCell<Counter>,
}

impl Cycles {
    /// `None` where the kernel refuses a counter (no perf support, or `perf_event_paranoid`).
    pub fn new() -> Option<Self> {
        let mut counter = Builder::new().kind(Hardware::CPU_CYCLES).build().ok()?;
        counter.enable().ok()?;
        Some(Self {
            counter: RefCell::new(counter),
        })
    }

    fn read(&self) -> u64 {
        self.counter
            .borrow_mut()
            .read()
            .expect("the cycle counter reads once it has opened")
    }
}

impl Measurement for Cycles {
    type Intermediate = u64;
    type Value = u64;

    fn start(&self) -> u64 {
        self.read()
    }

    fn end(&self, start: u64) -> u64 {
        self.read().saturating_sub(start)
    }

    fn add(&self, a: &u64, b: &u64) -> u64 {
        a + b
    }

    fn zero(&self) -> u64 {
        0
    }

    fn to_f64(&self, value: &u64) -> f64 {
        *value as f64
    }

    fn formatter(&self) -> &dyn ValueFormatter {
        &CyclesFormatter
    }
}

/// Cycles are shown as they are, per iteration (or per element of a throughput).
struct CyclesFormatter;

impl ValueFormatter for CyclesFormatter {
    fn scale_values(&self, _typical: f64, _values: &mut [f64]) -> &'static str {
        "cycles"
    }

    fn scale_throughputs(
        &self,
        _typical: f64,
        throughput: &Throughput,
        values: &mut [f64],
    ) -> &'static str {
        if let Throughput::Elements(count) = throughput {
            values.iter_mut().for_each(|v| *v /= *count as f64);
            "cycles/element"
        } else {
            "cycles"
        }
    }

    fn scale_for_machines(&self, _values: &mut [f64]) -> &'static str {
        "cycles"
    }
}
