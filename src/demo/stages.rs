//! The demo's sheet of the stages around lighting: fog in each mode (and per vertex), foliage
//! with and without the alpha test, a section view cut by user clip planes, and the color sum
//! with lighting off (added after texturing), and points: attenuated sprites, sprites of one
//! size, plain points, sprites without the alpha test. Each panel is one of the asset scenes
//! (`assets/scenes/fog.toml`, `foliage.toml`, `section.toml`, `particles.toml`), built into
//! the binary, with the state moved to the setting the panel names.

use std::path::Path;

use ffvk::gl::state::LightingMode;
use ffvk::scene::{render_scene, Scene};
use ffvk::Renderer;

use super::Panel;
use crate::Result;

const FOG: &str = include_str!("../../assets/scenes/fog.toml");
const FOLIAGE: &str = include_str!("../../assets/scenes/foliage.toml");
const SECTION: &str = include_str!("../../assets/scenes/section.toml");
const PARTICLES: &str = include_str!("../../assets/scenes/particles.toml");

/// One panel: its file name, its label, the scene's text, and what replaces what in it.
struct Variation {
    name: &'static str,
    label: &'static str,
    scene: &'static str,
    file: &'static str,
    edits: &'static [(&'static str, &'static str)],
    mode: Option<LightingMode>,
}

const FOG_MODE: &str = "mode = \"linear\"\n";

const VARIATIONS: [Variation; 16] = [
    Variation {
        name: "fog_linear",
        label: "GL_LINEAR fog, start 2.5 end 9",
        scene: FOG,
        file: "fog.toml",
        edits: &[],
        mode: None,
    },
    Variation {
        name: "fog_exp",
        label: "GL_EXP fog, density 0.25",
        scene: FOG,
        file: "fog.toml",
        edits: &[(FOG_MODE, "mode = \"exp\"\ndensity = 0.25\n")],
        mode: None,
    },
    Variation {
        name: "fog_exp2",
        label: "GL_EXP2 fog, density 0.18",
        scene: FOG,
        file: "fog.toml",
        edits: &[(FOG_MODE, "mode = \"exp2\"\ndensity = 0.18\n")],
        mode: None,
    },
    Variation {
        name: "fog_exp2_fastest",
        label: "GL_EXP2, GL_FASTEST hint",
        scene: FOG,
        file: "fog.toml",
        edits: &[(FOG_MODE, "mode = \"exp2\"\ndensity = 0.18\nhint = \"fastest\"\n")],
        mode: None,
    },
    Variation {
        name: "foliage_no_test",
        label: "leaves, no alpha test",
        scene: FOLIAGE,
        file: "foliage.toml",
        edits: &[("func = \"greater\"", "enabled = false\nfunc = \"greater\"")],
        mode: None,
    },
    Variation {
        name: "foliage_greater",
        label: "alpha test GL_GREATER 0.5",
        scene: FOLIAGE,
        file: "foliage.toml",
        edits: &[],
        mode: None,
    },
    Variation {
        name: "foliage_lequal",
        label: "GL_LEQUAL 0.5",
        scene: FOLIAGE,
        file: "foliage.toml",
        edits: &[("func = \"greater\"", "func = \"lequal\"")],
        mode: None,
    },
    Variation {
        name: "foliage_fogged",
        label: "alpha test after fog",
        scene: FOLIAGE,
        file: "foliage.toml",
        edits: &[(
            "[alpha_test]",
            "[fog]\nmode = \"linear\"\nstart = 2.0\nend = 6.0\ncolor = [0.55, 0.7, 0.85]\n\n[alpha_test]",
        )],
        mode: None,
    },
    Variation {
        name: "section",
        label: "GL_CLIP_PLANE0, two-sided",
        scene: SECTION,
        file: "section.toml",
        edits: &[],
        mode: None,
    },
    Variation {
        name: "section_vertex",
        label: "the same, vertex mode",
        scene: SECTION,
        file: "section.toml",
        edits: &[],
        mode: Some(LightingMode::Vertex),
    },
    Variation {
        name: "section_two_planes",
        label: "GL_CLIP_PLANE0 and 1",
        scene: SECTION,
        file: "section.toml",
        edits: &[(
            "[[meshes]]",
            "[[clip_planes]]\nequation = [0.0, -1.0, 0.0, 0.35]\n\n[[meshes]]",
        )],
        mode: None,
    },
    Variation {
        name: "color_sum_unlit",
        label: "unlit, GL_COLOR_SUM",
        scene: FOLIAGE,
        file: "foliage.toml",
        edits: &[(
            "[image]",
            "lighting = false\ncolor_sum = true\nsecondary_color = [0.35, 0.0, 0.25]\n\n[image]",
        )],
        mode: None,
    },
    Variation {
        name: "points_attenuated_sprites",
        label: "sprites, size / distance",
        scene: PARTICLES,
        file: "particles.toml",
        edits: &[],
        mode: None,
    },
    Variation {
        name: "points_one_size",
        label: "sprites of one size",
        scene: PARTICLES,
        file: "particles.toml",
        edits: &[
            ("distance_attenuation = [0.0, 0.0, 1.0]\n", ""),
            ("size = 40.0", "size = 13.0"),
        ],
        mode: None,
    },
    Variation {
        name: "points_squares",
        label: "GL_POINTS, no sprites",
        scene: PARTICLES,
        file: "particles.toml",
        edits: &[("sprite = true", "sprite = false")],
        mode: None,
    },
    Variation {
        name: "points_no_alpha_test",
        label: "sprites, no alpha test",
        scene: PARTICLES,
        file: "particles.toml",
        edits: &[("func = \"greater\"", "enabled = false\nfunc = \"greater\"")],
        mode: None,
    },
];

/// The stage sheet's panels, `size` pixels square.
pub fn stage_panels(renderer: &mut Renderer, size: u32) -> Result<Vec<Panel>> {
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut panels = Vec::new();
    for v in &VARIATIONS {
        let mut text = v.scene.to_owned();
        for (from, to) in v.edits {
            debug_assert!(text.contains(from), "{}: {from:?}", v.name);
            text = text.replacen(from, to, 1);
        }
        let mut scene = Scene::parse(&text, &assets.join(v.file))?;
        scene.set_size(size, size);
        panels.push(Panel {
            name: format!("stage_{}", v.name),
            label: v.label.to_owned(),
            image: render_scene(renderer, &scene, v.mode)?,
        });
    }
    Ok(panels)
}
