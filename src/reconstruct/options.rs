//! What a reconstruction is asked to do: the algorithm and its settings.

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
    /// The name used on the command line and in JSON output.
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::Wdm => "wdm",
            Algorithm::Crust => "crust",
            Algorithm::NnCrust => "nn-crust",
        }
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
    /// The name used on the command line (`--medial-axis pruned|raw`).
    pub fn name(self) -> &'static str {
        match self {
            MedialAxisMode::Pruned => "pruned",
            MedialAxisMode::Raw => "raw",
            MedialAxisMode::Omitted => "none",
        }
    }
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
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Options {
    algorithm: Algorithm,
    peeling: bool,
    label_rule: LabelRule,
    peeling_budget: usize,
    medial_axis: MedialAxisMode,
    detour_repair: bool,
    open_curves: bool,
    smoothing: bool,
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
            smoothing: false,
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
        self
    }

    /// How water-flow states become labels (see [`LabelRule`]); WDM only.
    pub fn with_label_rule(mut self, label_rule: LabelRule) -> Self {
        self.label_rule = label_rule;
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
        self
    }

    /// The medial axis returned (default [`MedialAxisMode::Pruned`]); WDM only.
    pub fn with_medial_axis(mut self, medial_axis: MedialAxisMode) -> Self {
        self.medial_axis = medial_axis;
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
        self
    }

    /// Smoothing (default off; every algorithm): every curve vertex is placed on a local
    /// fit of the samples around it, the points on no curve among them, and
    /// [`Reconstruction::curve_coords`](super::Reconstruction::curve_coords) gives the fitted
    /// positions (the input points without it). For dense noisy scans, where the curve runs
    /// through a band of samples several spacings wide: the fitted curve lies much closer to
    /// the true one than the samples do. Corners stay sharp, clean samples stay where they
    /// are (within a small fraction of their spacing), and the curves stay simple (no
    /// segment crosses another, decided exactly). The curves' points, the edges, the
    /// unassigned points and the medial axis are those of the unsmoothed curves
    /// (docs/design/smoothing.md).
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
}
