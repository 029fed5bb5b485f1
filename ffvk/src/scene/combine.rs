//! A texture unit's `combine` table: glTexEnv's `GL_COMBINE` parameters (GL 2.1 §3.8.13) with
//! GL's names in lowercase without `GL_`, table 6.19's defaults for those left out, and GL's
//! refusals (a dot product as the alpha function, a scale other than 1, 2 or 4) made by name;
//! a `GL_TEXTUREn` source ("texture0" .. "texture3") must name one of the mesh's units.

use super::file::CombineSpec;
use super::{Builder, SceneError};
use crate::gl::texture::{AlphaOperand, Combine, CombineFunc, CombineSource, RgbOperand, MAX_TEXTURE_UNITS};

/// The sources' words, `GL_TEXTURE0` .. `GL_TEXTURE3` last.
const SOURCES: [(&str, CombineSource); 4 + MAX_TEXTURE_UNITS] = [
    ("texture", CombineSource::Texture),
    ("constant", CombineSource::Constant),
    ("primary_color", CombineSource::PrimaryColor),
    ("previous", CombineSource::Previous),
    ("texture0", CombineSource::TextureUnit(0)),
    ("texture1", CombineSource::TextureUnit(1)),
    ("texture2", CombineSource::TextureUnit(2)),
    ("texture3", CombineSource::TextureUnit(3)),
];

/// The RGB operands' words; the alpha operands are the last two.
const RGB_OPERANDS: [(&str, RgbOperand); 4] = [
    ("src_color", RgbOperand::SrcColor),
    ("one_minus_src_color", RgbOperand::OneMinusSrcColor),
    ("src_alpha", RgbOperand::SrcAlpha),
    ("one_minus_src_alpha", RgbOperand::OneMinusSrcAlpha),
];

const ALPHA_OPERANDS: [(&str, AlphaOperand); 2] = [
    ("src_alpha", AlphaOperand::SrcAlpha),
    ("one_minus_src_alpha", AlphaOperand::OneMinusSrcAlpha),
];

/// A function's word: its GL name in lowercase without `GL_` (`add_signed`, `dot3_rgba`).
fn function_word(f: CombineFunc) -> String {
    f.gl_name().trim_start_matches("GL_").to_lowercase()
}

/// `words` quoted and joined as a message lists them.
fn quoted<'a>(words: impl IntoIterator<Item = &'a str>) -> String {
    words
        .into_iter()
        .map(|w| format!("{w:?}"))
        .collect::<Vec<_>>()
        .join(", ")
}

impl Builder<'_> {
    /// The `combine` table at `field` of a unit of a mesh with `units` texture units, read as a
    /// GL program's glTexEnv calls would set it on GL's initial state.
    pub(super) fn combine(
        &self,
        field: &str,
        spec: &CombineSpec,
        units: usize,
    ) -> Result<Combine, SceneError> {
        let f = |name: &str| format!("{field}.{name}");
        let mut c = Combine::default();
        if let Some(w) = &spec.rgb {
            c.rgb = self.combine_function(&f("rgb"), w, false)?;
        }
        if let Some(w) = &spec.alpha {
            c.alpha = self.combine_function(&f("alpha"), w, true)?;
        }
        if let Some(list) = &spec.rgb_sources {
            for (n, w) in self.arguments(&f("rgb_sources"), list, "GL_SRC0_RGB to GL_SRC2_RGB")? {
                c.rgb_sources[n] = self.combine_source(&format!("{field}.rgb_sources[{n}]"), w, units)?;
            }
        }
        if let Some(list) = &spec.alpha_sources {
            for (n, w) in self.arguments(&f("alpha_sources"), list, "GL_SRC0_ALPHA to GL_SRC2_ALPHA")? {
                c.alpha_sources[n] = self.combine_source(&format!("{field}.alpha_sources[{n}]"), w, units)?;
            }
        }
        if let Some(list) = &spec.rgb_operands {
            for (n, w) in self.arguments(&f("rgb_operands"), list, "GL_OPERAND0_RGB to GL_OPERAND2_RGB")? {
                c.rgb_operands[n] = self.word(&format!("{field}.rgb_operands[{n}]"), w, &RGB_OPERANDS)?;
            }
        }
        if let Some(list) = &spec.alpha_operands {
            let names = "GL_OPERAND0_ALPHA to GL_OPERAND2_ALPHA";
            for (n, w) in self.arguments(&f("alpha_operands"), list, names)? {
                c.alpha_operands[n] = self.alpha_operand(&format!("{field}.alpha_operands[{n}]"), w)?;
            }
        }
        if let Some(s) = spec.rgb_scale {
            c.rgb_scale = self.combine_scale(&f("rgb_scale"), s, "GL_RGB_SCALE")?;
        }
        if let Some(s) = spec.alpha_scale {
            c.alpha_scale = self.combine_scale(&f("alpha_scale"), s, "GL_ALPHA_SCALE")?;
        }
        Ok(c)
    }

    /// A list of at most three arguments' words, each with its n (Arg0 first).
    fn arguments<'s>(
        &self,
        field: &str,
        list: &'s [String],
        names: &str,
    ) -> Result<impl Iterator<Item = (usize, &'s str)>, SceneError> {
        if list.len() > 3 {
            return Err(self.field(
                field,
                format!(
                    "{} entries: expected at most 3, Arg0 to Arg2 ({names}); those left out keep GL's defaults",
                    list.len()
                ),
            ));
        }
        Ok(list.iter().map(String::as_str).enumerate())
    }

    /// `GL_COMBINE_RGB`'s word, or `GL_COMBINE_ALPHA`'s (`alpha`), which takes no dot product.
    fn combine_function(&self, field: &str, given: &str, alpha: bool) -> Result<CombineFunc, SceneError> {
        let words: Vec<(String, CombineFunc)> =
            CombineFunc::ALL.iter().map(|&f| (function_word(f), f)).collect();
        let allowed: Vec<(&str, CombineFunc)> = words
            .iter()
            .filter(|(_, f)| !alpha || f.is_alpha_function())
            .map(|(w, f)| (w.as_str(), *f))
            .collect();
        match words
            .iter()
            .find(|(w, f)| w == given && alpha && !f.is_alpha_function())
        {
            Some((_, dot)) => Err(self.field(
                field,
                format!(
                    "{given:?} for alpha: expected one of {} ({} combines RGB only: GL_INVALID_ENUM)",
                    quoted(allowed.iter().map(|(w, _)| *w)),
                    dot.gl_name()
                ),
            )),
            None => self.word(field, given, &allowed),
        }
    }

    /// A source's word; `GL_TEXTUREn` only for a unit the mesh has (`units` of them).
    fn combine_source(&self, field: &str, given: &str, units: usize) -> Result<CombineSource, SceneError> {
        let allowed = &SOURCES[..4 + units.min(MAX_TEXTURE_UNITS)];
        match SOURCES
            .iter()
            .find(|(w, s)| *w == given && s.unit().is_some_and(|n| n >= units))
        {
            Some((_, source)) => Err(self.field(
                field,
                format!(
                    "{given:?} reads unit {}, past the mesh's last texture unit ({}): expected one of {}",
                    source.unit().unwrap_or(0),
                    units.saturating_sub(1),
                    quoted(allowed.iter().map(|(w, _)| *w))
                ),
            )),
            None => self.word(field, given, allowed),
        }
    }

    /// An alpha argument's operand: a source's alpha or one minus it, never its color.
    fn alpha_operand(&self, field: &str, given: &str) -> Result<AlphaOperand, SceneError> {
        if given.ends_with("src_color") && RGB_OPERANDS.iter().any(|(w, _)| *w == given) {
            return Err(self.field(
                field,
                format!(
                    "{given:?} for alpha: expected one of {} (an alpha argument takes a source's alpha: GL_INVALID_ENUM)",
                    quoted(ALPHA_OPERANDS.iter().map(|(w, _)| *w))
                ),
            ));
        }
        self.word(field, given, &ALPHA_OPERANDS)
    }

    /// `GL_RGB_SCALE` or `GL_ALPHA_SCALE` (`name`): 1, 2 or 4.
    fn combine_scale(&self, field: &str, given: f64, name: &str) -> Result<f32, SceneError> {
        if [1.0, 2.0, 4.0].contains(&given) {
            return Ok(given as f32);
        }
        Err(self.field(
            field,
            format!("{given}: expected 1, 2 or 4 ({name}; GL_INVALID_VALUE in GL)"),
        ))
    }
}
