//! What every craft that manoeuvres shares, whatever its kind: the steering gear that moves a
//! rudder or a fin (saturation, lag, rate limit, and the commands a manoeuvre gives it), and
//! the record of a course that says whether a figure read off it is what its definition
//! assumes.
//!
//! A ship's rudder and a vehicle's fins are one steering gear, and a turning circle means the
//! same of either; each kind with manoeuvres (the ship, the vehicle) uses these, and none
//! imports another kind for them.

pub mod course;
pub mod steering;

pub use course::Course;
pub use steering::{Rudder, Series};
