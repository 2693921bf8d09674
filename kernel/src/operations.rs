//! What one call of a generated function costs, counted by the emitter.
//!
//! One type for everyone who counts: `eom-codegen` counts a program's operations with it and
//! chooses between strategies by [`Operations::cost`], every generated file states its
//! right-hand side's count as an `OPERATIONS` constant of this type, and `eom` reports it
//! (the catalog, a ship's interpreted program, the run summary).

/// Counts of the operations one call performs (`sin_cos` of one angle counts as one
/// trigonometric call).
///
/// ```
/// use eom_kernel::Operations;
/// let rhs = Operations { add: 8, mul: 18, div: 1, sqrt: 0, trig: 2 };
/// assert_eq!(rhs.arithmetic(), 27);
/// assert!(rhs.cost() < Operations { trig: 3, ..Operations::default() }.cost());
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Operations {
    /// Additions, subtractions and negations.
    pub add: u32,
    /// Multiplications.
    pub mul: u32,
    /// Divisions and reciprocals.
    pub div: u32,
    /// Square roots.
    pub sqrt: u32,
    /// Trigonometric calls.
    pub trig: u32,
}

impl Operations {
    /// A cost for choosing between strategies: trigonometric calls first, then divisions
    /// and square roots, then arithmetic.
    pub const fn cost(&self) -> (u32, u32, u32) {
        (self.trig, self.div + self.sqrt, self.add + self.mul)
    }

    /// Additions, multiplications and divisions together.
    pub const fn arithmetic(&self) -> u32 {
        self.add + self.mul + self.div
    }
}
