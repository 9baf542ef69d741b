//! Dispersion's spectrum (POV-Ray 3.7's SpectralBand): a dispersing refraction splits a ray
//! into bands of wavelength between 380 and 730 nm, each refracted by its own index and
//! weighted by its hue; the hues of all bands add up to white.

/// The violet end of the spectrum, in nm.
const VIOLET: f64 = 380.0;
/// The red end's distance from the violet end.
const WIDTH: f64 = 730.0 - VIOLET;
/// The wavelength at which the index of refraction is the nominal one.
const CENTRE: f64 = (VIOLET + 730.0) / 2.0;
/// The first wavelength of [`HUE_INTEGRAL`] and its step, in nm.
const TABLE_BASE: f64 = 375.0;
const TABLE_STEP: f64 = 5.0;

/// The colour of the spectrum integrated from its violet end up to each wavelength (375 nm,
/// 380 nm, … 740 nm): POV-Ray's table, from its older hue formula taken as colours pre-corrected
/// for a display gamma of 1.8.
#[rustfmt::skip]
const HUE_INTEGRAL: [[f32; 3]; 74] = [
    [0.0000, 0.0000, 0.0000], [0.0009, 0.0000, 0.0038], [0.0029, 0.0000, 0.0113],
    [0.0058, 0.0000, 0.0222], [0.0094, 0.0000, 0.0363], [0.0135, 0.0000, 0.0534],
    [0.0178, 0.0000, 0.0734], [0.0223, 0.0000, 0.0960], [0.0267, 0.0000, 0.1210],
    [0.0308, 0.0000, 0.1482], [0.0344, 0.0000, 0.1775], [0.0374, 0.0000, 0.2085],
    [0.0394, 0.0000, 0.2412], [0.0404, 0.0000, 0.2753], [0.0404, 0.0000, 0.3106],
    [0.0404, 0.0000, 0.3470], [0.0404, 0.0000, 0.3841], [0.0404, 0.0000, 0.4219],
    [0.0404, 0.0000, 0.4600], [0.0404, 0.0000, 0.4984], [0.0404, 0.0000, 0.5368],
    [0.0404, 0.0000, 0.5750], [0.0404, 0.0000, 0.6128], [0.0404, 0.0000, 0.6500],
    [0.0404, 0.0000, 0.6864], [0.0404, 0.0045, 0.7218], [0.0404, 0.0131, 0.7560],
    [0.0404, 0.0256, 0.7888], [0.0404, 0.0417, 0.8200], [0.0404, 0.0612, 0.8494],
    [0.0404, 0.0839, 0.8768], [0.0404, 0.1095, 0.9020], [0.0404, 0.1378, 0.9248],
    [0.0404, 0.1684, 0.9449], [0.0404, 0.2013, 0.9623], [0.0404, 0.2360, 0.9767],
    [0.0404, 0.2724, 0.9878], [0.0404, 0.3102, 0.9956], [0.0404, 0.3492, 0.9997],
    [0.0404, 0.3891, 1.0000], [0.0429, 0.4297, 1.0000], [0.0502, 0.4707, 1.0000],
    [0.0620, 0.5119, 1.0000], [0.0780, 0.5530, 1.0000], [0.0979, 0.5937, 1.0000],
    [0.1215, 0.6340, 1.0000], [0.1483, 0.6733, 1.0000], [0.1781, 0.7117, 1.0000],
    [0.2105, 0.7487, 1.0000], [0.2454, 0.7841, 1.0000], [0.2823, 0.8178, 1.0000],
    [0.3210, 0.8494, 1.0000], [0.3611, 0.8786, 1.0000], [0.4024, 0.9054, 1.0000],
    [0.4446, 0.9293, 1.0000], [0.4873, 0.9501, 1.0000], [0.5302, 0.9677, 1.0000],
    [0.5731, 0.9817, 1.0000], [0.6155, 0.9919, 1.0000], [0.6573, 0.9981, 1.0000],
    [0.6982, 1.0000, 1.0000], [0.7377, 1.0000, 1.0000], [0.7756, 1.0000, 1.0000],
    [0.8116, 1.0000, 1.0000], [0.8454, 1.0000, 1.0000], [0.8767, 1.0000, 1.0000],
    [0.9052, 1.0000, 1.0000], [0.9306, 1.0000, 1.0000], [0.9525, 1.0000, 1.0000],
    [0.9707, 1.0000, 1.0000], [0.9849, 1.0000, 1.0000], [0.9947, 1.0000, 1.0000],
    [0.9998, 1.0000, 1.0000], [1.0000, 1.0000, 1.0000],
];

/// One band of the spectrum (POV-Ray keeps both numbers in single precision).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Band {
    wavelength: f32,
    bandwidth: f32,
}

impl Band {
    /// Band `band` of `bands` equal ones.
    pub(super) fn new(band: u32, bands: u32) -> Band {
        Band {
            wavelength: (VIOLET
                + WIDTH * ((f64::from(band as f32) + 0.5) / f64::from(bands as f32)))
                as f32,
            bandwidth: (WIDTH / f64::from(bands as f32)) as f32,
        }
    }

    /// The relative index of refraction `eta` at this band's wavelength, for the relative
    /// dispersion `dispersion`: `eta · dispersion^(−(λ − 555) / 350)`.
    pub(super) fn ior(self, eta: f64, dispersion: f64) -> f64 {
        eta * dispersion.powf(-(f64::from(self.wavelength) - CENTRE) / WIDTH)
    }

    /// The band's colour: the spectrum's colour over the band, scaled so that the mean over
    /// all the bands is white.
    pub(super) fn hue(self) -> glam::DVec3 {
        let half = self.bandwidth / 2.0;
        let upper = hue_integral(f64::from(self.wavelength + half));
        let lower = hue_integral(f64::from(self.wavelength - half));
        (upper - lower) * (WIDTH / f64::from(self.bandwidth))
    }
}

/// [`HUE_INTEGRAL`] at `wavelength`, linearly interpolated (clamped to the table).
fn hue_integral(wavelength: f64) -> glam::DVec3 {
    let last = (HUE_INTEGRAL.len() - 1) as f64;
    let mut offset = ((wavelength - TABLE_BASE) / TABLE_STEP).clamp(0.0, last);
    let i = (offset as usize).min(HUE_INTEGRAL.len() - 2);
    offset -= i as f64;
    let at = |k: usize| {
        let [r, g, b] = HUE_INTEGRAL[k];
        glam::DVec3::new(f64::from(r), f64::from(g), f64::from(b))
    };
    (1.0 - offset) * at(i) + offset * at(i + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bands_hues_add_up_to_white() {
        for bands in [2, 3, 7, 20] {
            let mean = (0..bands)
                .map(|i| Band::new(i, bands).hue())
                .sum::<glam::DVec3>()
                / f64::from(bands);
            // (The table's ends are a little off white: 0.9938, 1, 0.9962.)
            assert!(
                (mean - glam::DVec3::ONE).abs().max_element() < 7e-3,
                "{bands} bands: {mean}"
            );
            let whole = hue_integral(730.0) - hue_integral(380.0);
            assert!(
                (mean - whole).abs().max_element() < 1e-5,
                "{bands} bands: {mean}"
            );
        }
    }

    #[test]
    fn violet_bends_more_than_red() {
        // Entering glass of dispersion 1.1 from air: eta = 1/1.5, dispersion ratio 1/1.1.
        let (violet, red) = (Band::new(0, 7), Band::new(6, 7));
        let (ev, er) = (
            violet.ior(1.0 / 1.5, 1.0 / 1.1),
            red.ior(1.0 / 1.5, 1.0 / 1.1),
        );
        assert!(
            1.0 / ev > 1.0 / er,
            "violet sees {} and red {}",
            1.0 / ev,
            1.0 / er
        );
        // The ends of the spectrum differ by the whole dispersion (less the bands' halves).
        let spread = (er / ev).ln() / 1.1f64.ln();
        assert!((spread - 6.0 / 7.0).abs() < 1e-6, "{spread}");
        // The middle band is the nominal index.
        assert!((Band::new(3, 7).ior(0.8, 1.2) - 0.8).abs() < 1e-12);
    }
}
