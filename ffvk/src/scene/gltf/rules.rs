//! What glTF 2.0 asks of a file that its validator does not check, each a problem naming its
//! JSON path: node transforms (matrix or TRS, unit rotations, affine matrices), accessors'
//! `normalized`, extensions used but not listed, and node graphs that are not trees.

use glam::Mat4;
use gltf::json::Value;

/// How far a node's rotation may be from unit length: |‖q‖ − 1| ≤ 0.01, what a writer that
/// rounds each component to two decimals can leave (each off by at most 0.005, and the
/// components' magnitudes summing to at most 2). A quaternion of length ℓ scales what it turns
/// by ℓ²; within this tolerance ffvk normalizes it ([`node_matrix`]), so that it only turns;
/// beyond it the file is refused.
pub(super) const ROTATION_TOLERANCE: f32 = 0.01;

/// What glTF 2.0 (3.5.3, "Transformations") asks of a node's transform and its validator does
/// not check: `matrix` or TRS, not both; a unit quaternion; a matrix decomposable to TRS, so
/// its last row (elements 3, 7, 11 and 15, column-major) is (0, 0, 0, 1).
pub(super) fn node_transform_problem(index: usize, node: &gltf::json::Node) -> Option<String> {
    if let Some(matrix) = &node.matrix {
        let trs: Vec<&str> = [
            ("translation", node.translation.is_some()),
            ("rotation", node.rotation.is_some()),
            ("scale", node.scale.is_some()),
        ]
        .into_iter()
        .filter_map(|(name, given)| given.then_some(name))
        .collect();
        if !trs.is_empty() {
            return Some(format!(
                "nodes[{index}].matrix: given with {}: expected either a matrix or translation, \
                 rotation and scale, not both",
                trs.join(", ")
            ));
        }
        let row = [matrix[3], matrix[7], matrix[11], matrix[15]];
        if row != [0.0, 0.0, 0.0, 1.0] {
            return Some(format!(
                "nodes[{index}].matrix: its last row (elements 3, 7, 11, 15) is {row:?}: expected \
                 [0.0, 0.0, 0.0, 1.0] (a matrix decomposable to translation, rotation and scale, \
                 not a projection)"
            ));
        }
    }
    if let Some(rotation) = &node.rotation {
        let q = rotation.0;
        let length = q.iter().map(|c| c * c).sum::<f32>().sqrt();
        // (NaN is off by more than any tolerance.)
        if (length - 1.0).abs() <= ROTATION_TOLERANCE {
            return None;
        }
        return Some(format!(
            "nodes[{index}].rotation: [{}, {}, {}, {}]: expected a unit quaternion (length 1 \
             within {ROTATION_TOLERANCE}; its length is {length})",
            q[0], q[1], q[2], q[3]
        ));
    }
    None
}

/// A node's local matrix: its `matrix`, or translation × rotation × scale with the rotation
/// normalized (it is unit within [`ROTATION_TOLERANCE`]; unnormalized, it would scale).
pub(super) fn node_matrix(node: &gltf::Node) -> Mat4 {
    match node.transform() {
        gltf::scene::Transform::Matrix { matrix } => Mat4::from_cols_array_2d(&matrix),
        gltf::scene::Transform::Decomposed {
            translation,
            rotation,
            scale,
        } => Mat4::from_scale_rotation_translation(
            scale.into(),
            glam::Quat::from_array(rotation).normalize(),
            translation.into(),
        ),
    }
}

/// glTF 2.0 (3.6.2.4, "Accessor Data Types" and 3.7.2.1): `normalized` is only for integer
/// vertex attributes; it "MUST NOT be set to true" for FLOAT or UNSIGNED_INT accessors, nor
/// for the indices of a primitive.
pub(super) fn accessor_problems(root: &gltf::json::Root) -> Vec<String> {
    use gltf::json::accessor::ComponentType;
    use gltf::json::validation::Checked;
    let mut problems = Vec::new();
    for (index, accessor) in root.accessors.iter().enumerate() {
        if !accessor.normalized {
            continue;
        }
        let component = match &accessor.component_type {
            Checked::Valid(t) => t.0,
            Checked::Invalid => continue,
        };
        let name = match component {
            ComponentType::F32 => "FLOAT (5126)",
            ComponentType::U32 => "UNSIGNED_INT (5125)",
            _ => continue,
        };
        problems.push(format!(
            "accessors[{index}].normalized: true with componentType {name}: expected false or \
             absent (only BYTE, UNSIGNED_BYTE, SHORT and UNSIGNED_SHORT data is normalized)"
        ));
    }
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            let Some(index) = primitive.indices.map(|i| i.value()) else {
                continue;
            };
            let Some(accessor) = root.accessors.get(index) else {
                continue;
            };
            let integer = !matches!(
                accessor.component_type,
                Checked::Valid(gltf::json::accessor::GenericComponentType(
                    ComponentType::F32 | ComponentType::U32
                ))
            );
            if accessor.normalized && integer {
                problems.push(format!(
                    "accessors[{index}].normalized: true for the indices of \
                     meshes[{m}].primitives[{p}]: expected false or absent (indices are not \
                     normalized)"
                ));
            }
        }
    }
    problems
}

/// The extension objects of the file ("extensions" members at any depth, outside `extras`)
/// whose names `extensionsUsed` leaves out, split in two: those ffvk reads (an error each: glTF
/// 2.0 says "All glTF extensions used in an asset MUST be listed in extensionsUsed", and a
/// reader that honoured the list would draw the file otherwise), and the names of the others
/// (which ffvk ignores either way: a warning).
pub(super) fn unlisted_extensions(raw: &Value) -> (Vec<String>, Vec<String>) {
    let used: Vec<&str> = raw
        .get("extensionsUsed")
        .and_then(Value::as_array)
        .into_iter()
        .flatten()
        .filter_map(Value::as_str)
        .collect();
    let (mut errors, mut others) = (Vec::new(), Vec::new());
    let mut stack: Vec<(String, &Value)> = vec![(String::new(), raw)];
    while let Some((path, value)) = stack.pop() {
        match value {
            Value::Array(items) => stack.extend(
                items
                    .iter()
                    .enumerate()
                    .rev()
                    .map(|(i, item)| (format!("{path}[{i}]"), item)),
            ),
            Value::Object(members) => {
                let mut children = Vec::new();
                for (key, item) in members {
                    let at = match path.is_empty() {
                        true => crate::scene::shorten(key),
                        false => format!("{path}.{}", crate::scene::shorten(key)),
                    };
                    match (key.as_str(), item) {
                        ("extras", _) => {}
                        ("extensions", Value::Object(extensions)) => {
                            for (name, object) in extensions {
                                let at = format!("{at}.{}", crate::scene::shorten(name));
                                if !used.contains(&name.as_str()) {
                                    if super::SUPPORTED_EXTENSIONS.contains(&name.as_str()) {
                                        errors.push(format!(
                                            "{at}: {name} is not listed in extensionsUsed: \
                                             expected every extension the file uses listed there"
                                        ));
                                    } else if !others.contains(name) {
                                        others.push(name.clone());
                                    }
                                }
                                children.push((at, object));
                            }
                        }
                        _ => children.push((at, item)),
                    }
                }
                children.reverse();
                stack.extend(children);
            }
            _ => {}
        }
    }
    (errors, others)
}

/// glTF 2.0 (3.5.2, "Nodes and Hierarchy"): "the node hierarchy MUST be a set of disjoint
/// strict trees": no node is a child twice (of one node or of two), none is its own ancestor,
/// and a scene's nodes are roots, each listed once. Each problem names the nodes. Run only on
/// a file whose node indices are valid; linear in the nodes and children.
pub(super) fn hierarchy_problems(root: &gltf::json::Root) -> Vec<String> {
    const SHOWN: usize = 8;
    let mut problems = Vec::new();
    let mut parent: Vec<Option<usize>> = vec![None; root.nodes.len()];
    for (index, node) in root.nodes.iter().enumerate() {
        for (k, child) in node.children.iter().flatten().enumerate() {
            let child = child.value();
            match parent.get(child).copied().flatten() {
                Some(first) if first == index => problems.push(format!(
                    "nodes[{index}].children[{k}]: node {child} is listed twice: expected each \
                     child once (glTF 2.0: the node hierarchy is a set of disjoint trees)"
                )),
                Some(first) => problems.push(format!(
                    "nodes[{index}].children[{k}]: node {child} is already a child of node \
                     {first}: expected one parent per node (glTF 2.0: the node hierarchy is a set \
                     of disjoint trees)"
                )),
                None => {
                    if let Some(slot) = parent.get_mut(child) {
                        *slot = Some(index);
                    }
                }
            }
            if problems.len() >= SHOWN {
                return problems;
            }
        }
    }
    // With one parent each, a node is its own ancestor when following parents from it comes
    // back: mark each chain as it is followed (1: on the chain being followed, 2: done).
    let mut state = vec![0u8; root.nodes.len()];
    for start in 0..root.nodes.len() {
        let mut chain = Vec::new();
        let mut at = Some(start);
        while let Some(node) = at.filter(|&n| state[n] == 0) {
            state[node] = 1;
            chain.push(node);
            at = parent[node];
        }
        if let Some(node) = at.filter(|&n| state[n] == 1) {
            // `node` is on the chain: the cycle runs from it, parent to child, back to it.
            let from = chain.iter().position(|&n| n == node).unwrap_or(0);
            let mut cycle: Vec<usize> = chain[from..].to_vec();
            cycle.reverse();
            // Named from its lowest node, whichever node the search came in by.
            let lowest = (0..cycle.len()).min_by_key(|&k| cycle[k]).unwrap_or(0);
            cycle.rotate_left(lowest);
            let mut names: Vec<String> = cycle.iter().take(SHOWN).map(usize::to_string).collect();
            if cycle.len() > SHOWN {
                names.push(format!("… ({} nodes in all)", cycle.len()));
            }
            names.push(cycle[0].to_string());
            problems.push(format!(
                "nodes {}: each is the next one's parent, so node {} is its own ancestor: \
                 expected the node hierarchy to be a set of disjoint trees",
                names.join(" → "),
                cycle[0]
            ));
        }
        for node in chain {
            state[node] = 2;
        }
    }
    for (s, scene) in root.scenes.iter().enumerate() {
        let mut listed = vec![false; root.nodes.len()];
        for (k, node) in scene.nodes.iter().enumerate() {
            let node = node.value();
            if let Some(p) = parent.get(node).copied().flatten() {
                problems.push(format!(
                    "scenes[{s}].nodes[{k}]: node {node} is a child of node {p}: expected the \
                     scene's root nodes only"
                ));
            } else if listed.get(node).copied().unwrap_or(false) {
                problems.push(format!(
                    "scenes[{s}].nodes[{k}]: node {node} is listed twice: expected each root once"
                ));
            }
            if let Some(slot) = listed.get_mut(node) {
                *slot = true;
            }
        }
    }
    problems
}
