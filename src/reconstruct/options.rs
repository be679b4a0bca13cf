//! What a reconstruction is asked to do: the algorithm and its settings, and which settings
//! do not apply together ([`Options::check`]).

use std::fmt;
use std::hash::{Hash, Hasher};

pub use super::wdm::LabelRule;

/// Which reconstruction algorithm to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Algorithm {
    /// WDM_CRUST (Peethambaran, Parakkat, Muthuganapathy): water-flow labeling.
    #[default]
    Wdm,
    /// The crust of Amenta, Bern and Eppstein: Delaunay edges between samples that survive
    /// when the Voronoi vertices are added to the point set.
    Crust,
    /// The nearest-neighbour crust of Dey and Kumar: each sample's nearest neighbour, plus
    /// its nearest "half neighbour" on the other side.
    NnCrust,
}

impl Algorithm {
    /// The stable name (`"wdm"`, `"crust"`, `"nn-crust"`), also its
    /// [`Display`](fmt::Display): the `"algorithm"` of the JSON output and what the
    /// bindings accept.
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::Wdm => "wdm",
            Algorithm::Crust => "crust",
            Algorithm::NnCrust => "nn-crust",
        }
    }
}

impl fmt::Display for Algorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Which medial axis a WDM reconstruction returns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum MedialAxisMode {
    /// WDM_MAT with the spurious branches that noise grows removed (see the `medial_axis`
    /// module docs for the rule); the default.
    #[default]
    Pruned,
    /// The paper's WDM_MAT: every finite Voronoi edge between two inner vertices.
    Raw,
    /// No medial axis: the reconstruction stops once the curves are assembled, and
    /// [`Reconstruction::medial_axis`](super::Reconstruction::medial_axis) is empty. For
    /// callers who want only the curves: the pruned axis is about half the time of a whole
    /// reconstruction (ARCHITECTURE.md, "Speed, threads and memory of the later stages"),
    /// and its balls are the memory peak.
    ///
    /// ```
    /// use wdm_crust::reconstruct::{reconstruct_with, MedialAxisMode, Options};
    /// let square = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [2.0, 2.0], [1.0, 2.0], [0.0, 2.0], [0.0, 1.0]];
    /// let options = Options::default().with_medial_axis(MedialAxisMode::Omitted);
    /// let rec = reconstruct_with(&square, &options)?;
    /// assert_eq!(rec.curves().len(), 1);
    /// assert!(rec.medial_axis().edges.is_empty());
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    Omitted,
}

impl MedialAxisMode {
    /// The stable name (`"pruned"`, `"raw"`, `"none"`), also its
    /// [`Display`](fmt::Display): what the bindings accept.
    pub fn name(self) -> &'static str {
        match self {
            MedialAxisMode::Pruned => "pruned",
            MedialAxisMode::Raw => "raw",
            MedialAxisMode::Omitted => "none",
        }
    }
}

impl fmt::Display for MedialAxisMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A setting of [`Options`] that only [`Algorithm::Wdm`] reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum WdmSetting {
    /// [`Options::with_peeling`].
    Peeling,
    /// [`Options::with_peeling_budget`].
    PeelingBudget,
    /// [`Options::with_medial_axis`].
    MedialAxis,
    /// [`Options::with_label_rule`].
    LabelRule,
    /// [`Options::with_detour_repair`].
    DetourRepair,
    /// [`Options::with_open_curves`].
    OpenCurves,
}

impl WdmSetting {
    /// Every setting, in the order [`Options::check`] looks at them.
    const ALL: [WdmSetting; 6] = [
        WdmSetting::MedialAxis,
        WdmSetting::Peeling,
        WdmSetting::PeelingBudget,
        WdmSetting::LabelRule,
        WdmSetting::DetourRepair,
        WdmSetting::OpenCurves,
    ];

    /// The setting in words (`"medial axis"`, `"peeling budget"`, ...), also its
    /// [`Display`](fmt::Display).
    pub fn name(self) -> &'static str {
        match self {
            WdmSetting::Peeling => "peeling",
            WdmSetting::PeelingBudget => "peeling budget",
            WdmSetting::MedialAxis => "medial axis",
            WdmSetting::LabelRule => "label rule",
            WdmSetting::DetourRepair => "detour repair",
            WdmSetting::OpenCurves => "open curves",
        }
    }

    fn bit(self) -> u8 {
        1 << (self as u8)
    }
}

impl fmt::Display for WdmSetting {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Settings of [`Options`] that do not apply together, found by [`Options::check`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum OptionsConflict {
    /// A WDM setting that asks a baseline algorithm for something it does not do.
    WdmOnly {
        /// The setting given.
        setting: WdmSetting,
        /// The baseline asked for.
        algorithm: Algorithm,
    },
    /// A peeling budget given with peeling off: there is no peeling for it to bound.
    BudgetWithoutPeeling,
}

impl OptionsConflict {
    /// Why the settings do not apply together, in words that do not depend on how the caller
    /// spells them: `"crust computes no medial axis"`.
    pub fn reason(&self) -> String {
        match *self {
            OptionsConflict::WdmOnly { setting, algorithm } => {
                let name = algorithm.name();
                match setting {
                    WdmSetting::MedialAxis => format!("{name} computes no medial axis"),
                    WdmSetting::Peeling | WdmSetting::PeelingBudget => {
                        format!("{name} runs one pass and has no peeling")
                    }
                    WdmSetting::LabelRule => {
                        format!(
                            "{name} labels no Voronoi vertices (the labels are WDM's water flow)"
                        )
                    }
                    WdmSetting::DetourRepair => format!("{name} has no detour repair"),
                    WdmSetting::OpenCurves => {
                        format!("{name} has no open-curve stage (its curves are its own edges)")
                    }
                }
            }
            OptionsConflict::BudgetWithoutPeeling => {
                "peeling is off, so there is no peeling for the budget to bound".to_string()
            }
        }
    }
}

impl fmt::Display for OptionsConflict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OptionsConflict::WdmOnly { setting, algorithm } => write!(
                f,
                "the {setting} setting does not apply to {algorithm}: {}",
                self.reason()
            ),
            OptionsConflict::BudgetWithoutPeeling => write!(
                f,
                "the peeling budget does not apply without peeling: {}",
                self.reason()
            ),
        }
    }
}

impl std::error::Error for OptionsConflict {}

/// The [`WdmSetting`]s set through a `with_*` method: what [`Options::check`] reads. Not
/// part of what options are equal by (they ask for the same reconstruction either way).
#[derive(Debug, Clone, Copy, Default)]
struct Given(u8);

impl Given {
    fn has(self, setting: WdmSetting) -> bool {
        self.0 & setting.bit() != 0
    }
}

impl PartialEq for Given {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl Eq for Given {}

impl Hash for Given {
    fn hash<H: Hasher>(&self, _: &mut H) {}
}

/// Reconstruction options, set through `with_*` methods so that new ones can come without
/// breaking callers.
///
/// ```
/// use wdm_crust::reconstruct::{Algorithm, Options};
/// let options = Options::default().with_algorithm(Algorithm::Crust).with_peeling(false);
/// assert_eq!(options.algorithm(), Algorithm::Crust);
/// assert!(!options.peeling());
/// ```
///
/// The settings of WDM ([`WdmSetting`]) are ignored by the baselines; [`check`](Self::check)
/// tells a caller who wants to refuse them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Options {
    algorithm: Algorithm,
    peeling: bool,
    label_rule: LabelRule,
    peeling_budget: usize,
    medial_axis: MedialAxisMode,
    detour_repair: bool,
    open_curves: bool,
    given: Given,
    smoothing: bool,
    thinning: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            algorithm: Algorithm::Wdm,
            peeling: true,
            label_rule: LabelRule::WaterReached,
            peeling_budget: 4,
            medial_axis: MedialAxisMode::Pruned,
            detour_repair: true,
            open_curves: true,
            given: Given(0),
            smoothing: false,
            thinning: true,
        }
    }
}

impl Options {
    /// The defaults: WDM_CRUST with peeling, the [`LabelRule::WaterReached`] labels, a
    /// peeling budget of 4, the detour repair and open curves.
    pub fn new() -> Self {
        Self::default()
    }

    /// The algorithm (default [`Algorithm::Wdm`]).
    pub fn with_algorithm(mut self, algorithm: Algorithm) -> Self {
        self.algorithm = algorithm;
        self
    }

    /// Nested curves (holes): rerun on the points the crust left untouched until none (or
    /// fewer than three) remain, and take the union. The paper's single pass never reaches
    /// a hole, so its inner curve would be lost. On by default; WDM only.
    pub fn with_peeling(mut self, peeling: bool) -> Self {
        self.peeling = peeling;
        self.given.0 |= WdmSetting::Peeling.bit();
        self
    }

    /// How water-flow states become labels (see [`LabelRule`]); WDM only.
    pub fn with_label_rule(mut self, label_rule: LabelRule) -> Self {
        self.label_rule = label_rule;
        self.given.0 |= WdmSetting::LabelRule.bit();
        self
    }

    /// Bounds the work of peeling: the extra passes together may run on at most this many
    /// times the input's point count (default 4), so a reconstruction costs at most about
    /// five single passes. Nested curves leave few points for the later passes and never
    /// meet the bound; inputs that are not curve samples do (uniform noise or a grid peel off
    /// a thin layer per pass and would take hundreds of passes).
    /// [`Reconstruction::peeling_budget_exhausted`](super::Reconstruction::peeling_budget_exhausted)
    /// tells when it stopped the peeling.
    pub fn with_peeling_budget(mut self, peeling_budget: usize) -> Self {
        self.peeling_budget = peeling_budget;
        self.given.0 |= WdmSetting::PeelingBudget.bit();
        self
    }

    /// The medial axis returned (default [`MedialAxisMode::Pruned`]); WDM only.
    pub fn with_medial_axis(mut self, medial_axis: MedialAxisMode) -> Self {
        self.medial_axis = medial_axis;
        self.given.0 |= WdmSetting::MedialAxis.bit();
        self
    }

    /// Outliers just outside a curve can make the water flow detour through them and skip a
    /// stretch of samples. The repair, run on the first pass before peeling, reattaches a
    /// skipped stretch (through the samples that name each other as nearest or half
    /// neighbours, NN-crust, along the path whose longest edge is shortest) in place of a
    /// detour whose longest edge is longer; the detour's points are then unassigned
    /// (ARCHITECTURE.md, "Outliers: detour repair"). On by default; WDM only. Changes
    /// nothing when every point is on a curve.
    pub fn with_detour_repair(mut self, detour_repair: bool) -> Self {
        self.detour_repair = detour_repair;
        self.given.0 |= WdmSetting::DetourRepair.bit();
        self
    }

    /// Open curves beside closed ones (default on; WDM only). The water flow draws only
    /// closed boundaries: on the samples of an open curve it closes a loop through a chord,
    /// wraps a thin loop around the samples, or leaves them out. With this on, the loops it
    /// is sure of are kept and every other point is joined into open chains (or loops) by
    /// proximity, and no point is ever on more than two edges (docs/design/open-curves.md).
    /// Off, the result is the water flow's alone: closed boundaries only, and on inputs
    /// that are not closed curves a point may be on more than two edges.
    ///
    /// ```
    /// // A half circle: one open chain from end to end.
    /// let arc: Vec<[f64; 2]> = (0..50)
    ///     .map(|i| {
    ///         let t = i as f64 / 49.0 * std::f64::consts::PI;
    ///         [t.cos(), t.sin()]
    ///     })
    ///     .collect();
    /// let rec = wdm_crust::reconstruct(&arc)?;
    /// assert_eq!(rec.curves().len(), 1);
    /// assert!(!rec.curves()[0].closed);
    /// assert_eq!(rec.edges().len(), 49);
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn with_open_curves(mut self, open_curves: bool) -> Self {
        self.open_curves = open_curves;
        self.given.0 |= WdmSetting::OpenCurves.bit();
        self
    }

    /// Smoothing (default off; every algorithm): every curve vertex is placed on a local
    /// fit of the samples around it, the points on no curve among them, and
    /// [`Reconstruction::curve_coords`](super::Reconstruction::curve_coords) gives the fitted
    /// positions (the input points without it). For dense noisy scans, where the curve runs
    /// through a band of samples several spacings wide: the fitted curve lies much closer to
    /// the true one than the samples do. Corners stay sharp, clean samples stay where they
    /// are (within a small fraction of their spacing), and the curves stay simple (no
    /// segment crosses another, decided exactly). The curves' points, the edges and the
    /// unassigned points are those of the unsmoothed curves; the pruned medial axis is that
    /// of the fitted closed curves (the raw axis stays the samples', it is the paper's
    /// WDM_MAT) (docs/design/smoothing.md).
    ///
    /// ```
    /// use wdm_crust::reconstruct::{reconstruct_with, Options};
    /// // 400 samples of the unit circle, each off it radially by up to 0.02 (about a
    /// // sample spacing), irregularly.
    /// let points: Vec<[f64; 2]> = (0..400)
    ///     .map(|k| {
    ///         let t = k as f64 * std::f64::consts::TAU / 400.0;
    ///         let r = 1.0 + 0.02 * (2.4 * k as f64).sin();
    ///         [r * t.cos(), r * t.sin()]
    ///     })
    ///     .collect();
    /// let rec = reconstruct_with(&points, &Options::new().with_smoothing(true))?;
    /// let off = |p: &[f64; 2]| (p[0].hypot(p[1]) - 1.0).powi(2);
    /// let rms = |ps: &[[f64; 2]]| (ps.iter().map(off).sum::<f64>() / ps.len() as f64).sqrt();
    /// let fitted: Vec<[f64; 2]> = rec.curves().iter().flat_map(|c| rec.curve_coords(c)).collect();
    /// assert!(rms(&fitted) < 0.7 * rms(&points), "{} {}", rms(&fitted), rms(&points));
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn with_smoothing(mut self, smoothing: bool) -> Self {
        self.smoothing = smoothing;
        self
    }

    /// Thinning of dense noisy bands (default on; WDM only, the baselines ignore it): when
    /// the points form a band many sample spacings wide (a dense noisy scan), they are
    /// covered by disks of a few noise widths and each disk is represented by its point
    /// nearest the disk's centroid; the curves are reconstructed through the
    /// representatives, and every other point is unassigned. Inputs whose noise is below
    /// about four spacings along the curve (every ε-sample, the sparse noisy ones) are never
    /// thinned. [`Reconstruction::thinned`](super::Reconstruction::thinned) tells whether it
    /// happened (docs/design/thinning.md).
    ///
    /// ```
    /// use wdm_crust::reconstruct::{reconstruct_with, Options};
    /// // 3000 points in a noisy band around the unit circle (σ = 0.03, about 15 spacings).
    /// let mut s = 1u64;
    /// let mut u = move || {
    ///     s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    ///     (s >> 11) as f64 / (1u64 << 53) as f64
    /// };
    /// let points: Vec<[f64; 2]> = (0..3000)
    ///     .map(|_| {
    ///         let t = std::f64::consts::TAU * u();
    ///         let g = (-2.0 * (1.0 - u()).ln()).sqrt() * (std::f64::consts::TAU * u()).cos();
    ///         let r = 1.0 + 0.03 * g;
    ///         [r * t.cos(), r * t.sin()]
    ///     })
    ///     .collect();
    /// let rec = reconstruct_with(&points, &Options::new())?;
    /// assert!(rec.thinned().is_some());
    /// assert_eq!(rec.curves().len(), 1);
    /// assert!(rec.curves()[0].closed);
    /// let raw = reconstruct_with(&points, &Options::new().with_thinning(false))?;
    /// assert!(raw.thinned().is_none());
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn with_thinning(mut self, thinning: bool) -> Self {
        self.thinning = thinning;
        self
    }

    /// See [`with_thinning`](Self::with_thinning).
    pub fn thinning(&self) -> bool {
        self.thinning
    }

    /// See [`with_smoothing`](Self::with_smoothing).
    pub fn smoothing(&self) -> bool {
        self.smoothing
    }

    /// See [`with_open_curves`](Self::with_open_curves).
    pub fn open_curves(&self) -> bool {
        self.open_curves
    }

    /// See [`with_algorithm`](Self::with_algorithm).
    pub fn algorithm(&self) -> Algorithm {
        self.algorithm
    }

    /// See [`with_peeling`](Self::with_peeling).
    pub fn peeling(&self) -> bool {
        self.peeling
    }

    /// See [`with_label_rule`](Self::with_label_rule).
    pub fn label_rule(&self) -> LabelRule {
        self.label_rule
    }

    /// See [`with_peeling_budget`](Self::with_peeling_budget).
    pub fn peeling_budget(&self) -> usize {
        self.peeling_budget
    }

    /// See [`with_medial_axis`](Self::with_medial_axis).
    pub fn medial_axis(&self) -> MedialAxisMode {
        self.medial_axis
    }

    /// See [`with_detour_repair`](Self::with_detour_repair).
    pub fn detour_repair(&self) -> bool {
        self.detour_repair
    }

    /// Whether the settings given (through a `with_*` method, even with the default value)
    /// apply together; the first conflict if not.
    ///
    /// A setting of WDM ([`WdmSetting`]) given with [`Algorithm::Crust`] or
    /// [`Algorithm::NnCrust`] conflicts when it asks for something the baseline does not do:
    /// a medial axis ([`MedialAxisMode::Pruned`] or [`MedialAxisMode::Raw`]), peeling
    /// (`with_peeling(true)`), a peeling budget, a label rule, the detour repair
    /// (`with_detour_repair(true)`), open curves (either way: the baseline's chains are its
    /// own edges, not the open-curve stage's). A setting that turns off what the baseline
    /// lacks anyway ([`MedialAxisMode::Omitted`], `with_peeling(false)`,
    /// `with_detour_repair(false)`) does not: the result is what it asks for, so one set of
    /// such options serves every algorithm. A peeling budget given with peeling off
    /// conflicts too.
    ///
    /// [`reconstruct_with`](super::reconstruct_with) does not call it (a baseline ignores the
    /// WDM settings); the command line and the Python package do, and refuse the conflict.
    ///
    /// ```
    /// use wdm_crust::reconstruct::{Algorithm, MedialAxisMode, Options, OptionsConflict, WdmSetting};
    /// let crust = Options::new().with_algorithm(Algorithm::Crust);
    /// assert_eq!(crust.check(), Ok(()));
    /// let raw = crust.with_medial_axis(MedialAxisMode::Raw);
    /// assert_eq!(
    ///     raw.check(),
    ///     Err(OptionsConflict::WdmOnly { setting: WdmSetting::MedialAxis, algorithm: Algorithm::Crust })
    /// );
    /// assert_eq!(raw.check().unwrap_err().reason(), "crust computes no medial axis");
    /// // Turning off what the crust does not have anyway is fine.
    /// assert_eq!(crust.with_medial_axis(MedialAxisMode::Omitted).with_peeling(false).check(), Ok(()));
    /// // A budget for a peeling that is off.
    /// let single = Options::new().with_peeling(false).with_peeling_budget(2);
    /// assert_eq!(single.check(), Err(OptionsConflict::BudgetWithoutPeeling));
    /// ```
    pub fn check(&self) -> Result<(), OptionsConflict> {
        if self.algorithm != Algorithm::Wdm {
            for setting in WdmSetting::ALL {
                if self.given.has(setting) && self.asks_for(setting) {
                    return Err(OptionsConflict::WdmOnly {
                        setting,
                        algorithm: self.algorithm,
                    });
                }
            }
        }
        if self.given.has(WdmSetting::PeelingBudget) && !self.peeling {
            return Err(OptionsConflict::BudgetWithoutPeeling);
        }
        Ok(())
    }

    /// Whether `setting`, as set, asks for a part of WDM (rather than turning one off).
    fn asks_for(&self, setting: WdmSetting) -> bool {
        match setting {
            WdmSetting::Peeling => self.peeling,
            WdmSetting::MedialAxis => self.medial_axis != MedialAxisMode::Omitted,
            WdmSetting::DetourRepair => self.detour_repair,
            WdmSetting::PeelingBudget | WdmSetting::LabelRule | WdmSetting::OpenCurves => true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wdm_settings_that_ask_a_baseline_for_what_it_lacks_conflict() {
        for algorithm in [Algorithm::Crust, Algorithm::NnCrust] {
            let base = Options::new().with_algorithm(algorithm);
            let conflict = |setting| Err(OptionsConflict::WdmOnly { setting, algorithm });
            assert_eq!(base.check(), Ok(()));
            for mode in [MedialAxisMode::Pruned, MedialAxisMode::Raw] {
                let options = base.with_medial_axis(mode);
                assert_eq!(options.check(), conflict(WdmSetting::MedialAxis));
            }
            assert_eq!(
                base.with_peeling(true).check(),
                conflict(WdmSetting::Peeling)
            );
            assert_eq!(
                base.with_peeling_budget(4).check(),
                conflict(WdmSetting::PeelingBudget)
            );
            assert_eq!(
                base.with_label_rule(LabelRule::WaterReached).check(),
                conflict(WdmSetting::LabelRule)
            );
            assert_eq!(
                base.with_detour_repair(true).check(),
                conflict(WdmSetting::DetourRepair)
            );
            for on in [true, false] {
                assert_eq!(
                    base.with_open_curves(on).check(),
                    conflict(WdmSetting::OpenCurves)
                );
            }
            // Off where the baseline has nothing to turn off.
            let off = base
                .with_medial_axis(MedialAxisMode::Omitted)
                .with_peeling(false)
                .with_detour_repair(false);
            assert_eq!(off.check(), Ok(()));
            // The order the settings were given in does not matter, nor the algorithm's place.
            let late = Options::new()
                .with_medial_axis(MedialAxisMode::Raw)
                .with_algorithm(algorithm);
            assert_eq!(late.check(), conflict(WdmSetting::MedialAxis));
            assert_eq!(
                late.check().unwrap_err().to_string(),
                format!(
                    "the medial axis setting does not apply to {0}: {0} computes no medial axis",
                    algorithm.name()
                )
            );
        }
    }

    #[test]
    fn wdm_takes_every_setting_but_a_budget_without_peeling() {
        let every = Options::new()
            .with_algorithm(Algorithm::Wdm)
            .with_medial_axis(MedialAxisMode::Raw)
            .with_peeling(true)
            .with_peeling_budget(2)
            .with_label_rule(LabelRule::WaterReached)
            .with_detour_repair(false)
            .with_open_curves(false);
        assert_eq!(every.check(), Ok(()));
        assert_eq!(
            every.with_peeling(false).check(),
            Err(OptionsConflict::BudgetWithoutPeeling)
        );
        assert_eq!(Options::new().with_peeling(false).check(), Ok(()));
    }

    #[test]
    fn options_are_equal_by_what_they_ask_for() {
        assert_eq!(Options::new(), Options::new().with_peeling(true));
        assert_ne!(Options::new(), Options::new().with_peeling(false));
        let hash = |o: &Options| {
            use std::collections::hash_map::DefaultHasher;
            let mut h = DefaultHasher::new();
            o.hash(&mut h);
            h.finish()
        };
        assert_eq!(
            hash(&Options::new()),
            hash(&Options::new().with_peeling_budget(4))
        );
    }
}
