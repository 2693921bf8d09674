//! What a manoeuvre's run reads off the course once it has ended: a turning circle's,
//! a zig-zag's, a pull-out's, a spiral's and a crash stop's figures, each given only where what
//! it assumes held, else a note says why.

use super::*;

impl Driver<'_> {
    pub(super) fn figures(&self, (t, end): (f64, &DriveState)) -> Figures {
        let Some(execute) = self.log.execute else {
            return self.with_stop_note(Figures {
                notes: vec!["the run ended before the execute".into()],
                ..Figures::default()
            });
        };
        let course = self.log.course.clone().unwrap_or_default();
        let mut figures = match self.manoeuvre.kind {
            ManoeuvreKind::TurningCircle { .. } => self.turning_figures(&execute, &course),
            ManoeuvreKind::ZigZag { heading, .. } => {
                self.zigzag_figures(&execute, heading, &course)
            }
            ManoeuvreKind::PullOut { release, .. } => {
                let at_release = self.log.release.as_ref().map(|y| (release, y));
                // The final yaw rate is the run's end's, which a stopped run did not reach.
                let at_end = self.stopped.is_none().then_some((t, end));
                pull_out_figures(release, (at_release, at_end), &course)
            }
            ManoeuvreKind::Series(_) => Figures::default(),
            ManoeuvreKind::Spiral(Spiral { settle, length, .. })
            | ManoeuvreKind::ReverseSpiral(ReverseSpiral { settle, length, .. }) => {
                spiral::figures(self.spiral_curve(&execute, (settle, length), &course))
            }
            // Read where the ship stops, which is what the course's conditions rule out
            // elsewhere.
            ManoeuvreKind::CrashStop { .. } => {
                return self.with_stop_note(self.crash_stop_figures(&execute, end));
            }
        };
        figures.notes.extend(course.notes());
        self.with_stop_note(figures)
    }

    /// `figures` with, first among its notes, where the stop condition ended the run and
    /// which figures it had not given by then, if it did.
    pub(super) fn with_stop_note(&self, mut figures: Figures) -> Figures {
        let (Some(t), Some(stop)) = (self.stopped, self.stop) else {
            return figures;
        };
        let absent: Vec<&str> = (figures.values.iter())
            .filter(|(_, value)| value.is_none())
            .map(|(key, _)| *key)
            .collect();
        let what = match (absent.is_empty(), self.log.execute.is_some()) {
            (_, false) => "before the execute".to_owned(),
            (true, true) => "after every figure had been read".to_owned(),
            (false, true) => format!("before the run gave {}", absent.join(", ")),
        };
        let note =
            format!("stopped at t = {t:.1} s where `{stop}` first held ({STOP_KEY}), {what}");
        figures.notes.insert(0, note);
        figures
    }

    /// A spiral's curve: its points up to the instant the ship went astern or stopped (none
    /// after), whether they cover every setpoint, and the steady turns over their range of δ,
    /// traced from the approach's speed.
    pub(super) fn spiral_curve(
        &self,
        execute: &DriveState,
        (settle, length): (spiral::Settle, f64),
        course: &Course,
    ) -> SpiralCurve {
        let mut points = self
            .spiral
            .as_ref()
            .map_or_else(Vec::new, |p| p.points.clone());
        let measured = points.len();
        points.retain(|p| course.broken_by(p.at).is_none());
        let incomplete = match (points.len() < measured, self.spiral_done(), self.stopped) {
            (true, _, _) => course
                .broken_by(f64::INFINITY)
                .map(|why| format!("{why}: no point taken from then on is given")),
            (false, true, _) => None,
            (false, false, Some(t)) => Some(format!(
                "the run was stopped at t = {t:.1} s ({STOP_KEY}) before every setpoint was \
                 measured"
            )),
            (false, false, None) => Some(
                "the run ended before every setpoint was measured: lengthen duration_s or \
                 max_hold_s"
                    .to_owned(),
            ),
        };
        let mut curve = SpiralCurve {
            points,
            settle,
            incomplete,
            steady: Err("the spiral measured no point".to_owned()),
        };
        // A direct spiral's angles are its own; a reverse spiral's are those it measured.
        let range = match &self.manoeuvre.kind {
            ManoeuvreKind::Spiral(spiral) => Some(spiral::range(&spiral.rudders)),
            _ => (!curve.points.is_empty()).then(|| curve.rudder_range()),
        };
        if let Some(range) = range {
            let speed = execute[0].hypot(execute[1]);
            curve.steady = steady_turns(self.model, (speed, length), range);
        }
        curve
    }

    /// The crash stop's figures at the instant the ship stops (u = 0), from the execute:
    /// the track reach (the distance midship ran), the head reach and the lateral deviation
    /// (midship's displacement along and across the approach's heading), the time to stop.
    pub(super) fn crash_stop_figures(&self, execute: &DriveState, end: &DriveState) -> Figures {
        let stop = self.event(Watch::Stopped);
        let (s, c) = execute[5].sin_cos();
        let offset = |y: &DriveState| {
            let (dx, dy) = (y[3] - execute[3], y[4] - execute[4]);
            (dx * c + dy * s, -dx * s + dy * c)
        };
        let mut notes = Vec::new();
        let mut marks = vec![("execute".to_owned(), [execute[3], execute[4]])];
        match stop {
            Some((_, y)) => {
                let (head, lateral) = offset(&y);
                let label = format!("stopped: head reach {head:.1} m, lateral {lateral:.1} m");
                marks.push((label, [y[3], y[4]]));
            }
            // A run the stop condition ended says so once, in the note of every figure.
            None if self.stopped.is_some() => {}
            // What it was doing then says whether a longer run would stop it: still slowing
            // down, or settled into a turn ahead.
            None => notes.push(format!(
                "the ship had not stopped by the end of the run (t = {} s): it still made u = \
                 {:.3} m/s there, turning at r = {:.3}°/s; lengthen duration_s if u is still \
                 falling",
                self.manoeuvre.duration,
                end[0],
                end[2].to_degrees()
            )),
        }
        Figures {
            values: vec![
                ("track_reach_m", stop.map(|(_, y)| y[7] - execute[7])),
                ("head_reach_m", stop.map(|(_, y)| offset(&y).0)),
                ("lateral_deviation_m", stop.map(|(_, y)| offset(&y).1.abs())),
                (
                    "time_to_stop_s",
                    stop.map(|(t, _)| t - self.manoeuvre.execute),
                ),
            ],
            side: None,
            notes,
            marks,
            spiral: None,
        }
    }

    pub(super) fn event(&self, wanted: Watch) -> Option<(f64, DriveState)> {
        self.log
            .events
            .iter()
            .find(|(watch, _, _)| *watch == wanted)
            .map(|(_, t, y)| (*t, *y))
    }

    /// The turning circle's figures, each where the condition it assumes held
    /// ([`Course`]): advance and transfer at 90°, the tactical diameter at 180° while the ship
    /// goes ahead; the steady radius and speed once the turn has settled.
    pub(super) fn turning_figures(&self, execute: &DriveState, course: &Course) -> Figures {
        let psi0 = execute[5];
        // (advance, transfer): the displacement of midship in the axes of the approach.
        let offset = |y: &DriveState| {
            let (dx, dy) = (y[3] - execute[3], y[4] - execute[4]);
            let (s, c) = psi0.sin_cos();
            (dx * c + dy * s, -dx * s + dy * c)
        };
        let t_exec = self.manoeuvre.execute;
        let mut notes = Vec::new();
        let mut holding = |angle: f64, what: &str| {
            let (t, y) = self.event(Watch::HeadingChange(angle))?;
            match course.broken_by(t) {
                Some(why) => {
                    notes.push(format!(
                        "{what} not given: {why}, before the heading changed by {:.0}°",
                        angle.to_degrees()
                    ));
                    None
                }
                None => Some((t, y)),
            }
        };
        let at_90 = holding(PI / 2.0, "advance and transfer");
        let at_180 = holding(PI, "the tactical diameter");
        // A drifting circle's first and second whole turns.
        let turns = (self.model.drifts()).then(|| {
            (
                holding(2.0 * PI, "the drift"),
                holding(4.0 * PI, "the drift"),
            )
        });
        // The steady turn is read at the end of the run, which a stopped run did not reach.
        let steady = match self.stopped {
            Some(_) => None,
            None => course.steady().map_err(|why| notes.push(why)).ok(),
        };
        let mut marks = vec![("execute".to_owned(), [execute[3], execute[4]])];
        if let Some((_, y)) = at_90 {
            let (advance, transfer) = offset(&y);
            let label = format!(
                "90°: advance {advance:.1} m, transfer {:.1} m",
                transfer.abs()
            );
            marks.push((label, [y[3], y[4]]));
        }
        if let Some((_, y)) = at_180 {
            let label = format!("180°: tactical diameter {:.1} m", offset(&y).1.abs());
            marks.push((label, [y[3], y[4]]));
        }
        let mut values = vec![
            ("advance_90_m", at_90.map(|(_, y)| offset(&y).0)),
            ("transfer_90_m", at_90.map(|(_, y)| offset(&y).1.abs())),
            (
                "tactical_diameter_m",
                at_180.map(|(_, y)| offset(&y).1.abs()),
            ),
            (
                "steady_turning_radius_m",
                steady.map(|(speed, r)| speed / r.abs()),
            ),
            ("steady_speed_m_s", steady.map(|(speed, _)| speed)),
            ("t_90_s", at_90.map(|(t, _)| t - t_exec)),
            ("t_180_s", at_180.map(|(t, _)| t - t_exec)),
        ];
        // The displacement over the second whole turn, and how long it took.
        let drift = match turns {
            Some((Some((t1, y1)), Some((t2, y2)))) => Some((y2[3] - y1[3], y2[4] - y1[4], t2 - t1)),
            Some(_) => {
                notes.push(
                    "the drift not given: the turn did not reach 720° of heading change (or \
                     stopped going ahead) by the end; lengthen duration_s"
                        .to_owned(),
                );
                None
            }
            None => None,
        };
        if turns.is_some() {
            values.extend([
                ("drift_m_per_turn", drift.map(|(n, e, _)| n.hypot(e))),
                (
                    "drift_toward_deg",
                    drift.map(|(n, e, _)| e.atan2(n).to_degrees().rem_euclid(360.0)),
                ),
                ("turn_period_s", drift.map(|(_, _, period)| period)),
            ]);
        }
        Figures {
            values,
            side: Some(if course.turned() > 0.0 {
                "starboard"
            } else {
                "port"
            }),
            notes,
            marks,
            spiral: None,
        }
    }

    /// The zig-zag's figures; none where the ship went astern or stopped before the last
    /// reversal or overshoot they are read from.
    pub(super) fn zigzag_figures(
        &self,
        execute: &DriveState,
        heading_a: f64,
        course: &Course,
    ) -> Figures {
        let psi0 = execute[5];
        // Instants after the ship went astern or stopped are not the zig-zag's.
        let holds = |t: f64| course.broken_by(t).is_none();
        let switches: Vec<(f64, DriveState)> = self
            .log
            .events
            .iter()
            .filter(|(w, t, _)| !matches!(w, Watch::YawRateZero) && holds(*t))
            .map(|(_, t, y)| (*t, *y))
            .collect();
        // The k-th overshoot: the largest heading change past the k-th reversal, where r = 0.
        let overshoot = |k: usize| {
            let after = switches.get(k)?.0;
            let side = if k.is_multiple_of(2) {
                self.side
            } else {
                -self.side
            };
            let (_, _, y) = self
                .log
                .events
                .iter()
                .find(|(w, t, _)| *w == Watch::YawRateZero && *t > after)
                .filter(|(_, t, _)| holds(*t))?;
            Some((side * (y[5] - psi0) - heading_a).to_degrees())
        };
        let t_exec = self.manoeuvre.execute;
        let mut notes = Vec::new();
        if switches.len() < 3 && self.stopped.is_none() {
            let reversals = crate::counted(switches.len(), "reversal", "reversals");
            notes.push(format!(
                "{reversals} by the end: the period needs three; lengthen duration_s"
            ));
        }
        Figures {
            values: vec![
                ("first_overshoot_deg", overshoot(0)),
                ("second_overshoot_deg", overshoot(1)),
                ("reach_time_s", switches.first().map(|(t, _)| t - t_exec)),
                ("period_s", switches.get(2).map(|(t, _)| t - switches[0].0)),
                (
                    "initial_turning_distance_m",
                    switches.first().map(|(_, y)| y[7] - execute[7]),
                ),
            ],
            side: None,
            notes,
            marks: vec![],
            spiral: None,
        }
    }
}

/// An instant of a run: its time and state.
type Instant<'a> = (f64, &'a DriveState);

/// A pull-out released at `release` (s): the yaw rate when the rudder is released,
/// `at_release` (t, state), and at the end, `at_end` (t, state; `None` where the run was
/// stopped before it); a course-stable ship's dies out, an unstable one's settles to a
/// residual turn. Neither is read after the ship went astern or stopped
/// ([`Course::broken_by`]).
fn pull_out_figures(
    release: f64,
    (at_release, at_end): (Option<Instant<'_>>, Option<Instant<'_>>),
    course: &Course,
) -> Figures {
    let mut notes = Vec::new();
    let mut read = |(t, y): (f64, &DriveState), what: &str| match course.broken_by(t) {
        Some(why) => {
            notes.push(format!("{what} not given: {why}"));
            None
        }
        None => Some(y[2].to_degrees()),
    };
    let at_release = at_release.and_then(|at| read(at, "the yaw rate at the release"));
    let at_end = at_end.and_then(|at| read(at, "the final yaw rate"));
    Figures {
        values: vec![
            ("release_s", Some(release)),
            ("yaw_rate_at_release_deg_s", at_release),
            ("final_yaw_rate_deg_s", at_end),
        ],
        side: None,
        notes,
        marks: vec![],
        spiral: None,
    }
}
