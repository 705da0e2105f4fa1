//! glTF 2.0 (.gltf with external or embedded buffers, .glb): the document is parsed and validated
//! by the `gltf` crate; buffers, accessors and images are read here, with every offset, stride
//! and count checked against the bytes present (the crate's own reader panics or allocates by
//! the claimed count on some malformed files). The default scene's node hierarchy is flattened
//! to world space; `alphaMode: MASK` materials keep the alpha channel of their base-colour
//! texture (times the base-colour factor) and cutoff. Only those textures are decoded.

use super::{AlphaMask, Material, Scene, SceneError, SideFiles};
use aokit_shaders::glam::{Mat4, Vec2, Vec3};
use gltf::accessor::{DataType, Dimensions};
use std::path::Path;

/// At least this many triangles may be instanced from any file (see [`triangle_budget`]).
const MIN_TRIANGLE_BUDGET: usize = 1 << 22;

/// The most triangles a glTF file of `bytes` bytes (with its buffers) may expand to through
/// instancing: 16 per byte, and at least [`MIN_TRIANGLE_BUDGET`]. A node hierarchy that
/// instances meshes more often than that is refused (before anything is read) instead of
/// exhausting memory.
fn triangle_budget(bytes: usize) -> usize {
    bytes.saturating_mul(16).max(MIN_TRIANGLE_BUDGET)
}

pub(super) fn load_bytes(path: &Path, bytes: &[u8], side_files: SideFiles) -> Result<Scene, SceneError> {
    let bad = |problem: String| SceneError::malformed(path, "glTF", problem);
    check_glb_header(bytes).map_err(bad)?;
    let gltf::Gltf { document: doc, blob } =
        gltf::Gltf::from_slice_without_validation(bytes).map_err(|e| bad(e.to_string()))?;
    // gltf-json's validation looks up each POSITION accessor without a bounds check.
    let json = doc.into_json();
    check_position_indices(&json).map_err(bad)?;
    let doc = gltf::Document::from_json(json).map_err(|e| bad(e.to_string()))?;
    let buffers = load_buffers(&doc, blob, side_files).map_err(bad)?;
    let materials =
        doc.materials().map(|m| material(&m, &doc, &buffers, side_files)).collect::<Result<_, _>>().map_err(bad)?;
    let mut scene = Scene { name: path.display().to_string(), materials, ..Default::default() };
    let root = doc.default_scene().or_else(|| doc.scenes().next());
    let Some(root) = root else {
        return Err(bad("no scene in the document".into()));
    };
    // The node hierarchy, flattened (in the order the triangles are emitted).
    let mut visited = vec![false; doc.nodes().len()];
    let mut instances = Vec::new();
    let mut stack: Vec<(gltf::Node, Mat4)> = root.nodes().map(|n| (n, Mat4::IDENTITY)).collect();
    while let Some((node, parent)) = stack.pop() {
        // A strict tree (glTF 2.0 §3.5.3); a cycle would never end, a shared child multiply.
        if std::mem::replace(&mut visited[node.index()], true) {
            return Err(bad(format!("node {} is reached twice: the node hierarchy is not a tree", node.index())));
        }
        let world = parent * Mat4::from_cols_array_2d(&node.transform().matrix());
        stack.extend(node.children().map(|c| (c, world)));
        if let Some(mesh) = node.mesh() {
            instances.push((mesh, world));
        }
    }
    // What instancing expands to, from the accessors' counts, before anything is read.
    let claimed = instances
        .iter()
        .flat_map(|(mesh, _)| mesh.primitives())
        .filter(|p| p.mode() == gltf::mesh::Mode::Triangles)
        .map(|p| p.indices().or_else(|| p.get(&gltf::Semantic::Positions)).map_or(0, |a| a.count() / 3))
        .fold(0usize, usize::saturating_add);
    let total_bytes = buffers.iter().fold(bytes.len(), |n, b| n.saturating_add(b.len()));
    let budget = triangle_budget(total_bytes);
    if claimed > budget {
        return Err(bad(format!(
            "the scene's primitives claim {claimed} triangles (instances included), more than the {budget} a file of {total_bytes} bytes may expand to"
        )));
    }
    for (mesh, world) in instances {
        for prim in mesh.primitives() {
            add_primitive(&mut scene, &prim, &buffers, world)
                .map_err(|problem| bad(format!("mesh {} primitive {}: {problem}", mesh.index(), prim.index())))?;
        }
    }
    Ok(scene)
}

/// Every primitive attribute must name an existing accessor (checked before gltf-json's
/// validation, which indexes the POSITION accessor unchecked).
fn check_position_indices(json: &gltf::json::Root) -> Result<(), String> {
    for (m, mesh) in json.meshes.iter().enumerate() {
        for (p, prim) in mesh.primitives.iter().enumerate() {
            for (semantic, index) in &prim.attributes {
                if index.value() >= json.accessors.len() {
                    let name = match semantic {
                        gltf::json::validation::Checked::Valid(s) => s.to_string(),
                        gltf::json::validation::Checked::Invalid => "(invalid)".into(),
                    };
                    return Err(format!(
                        "mesh {m} primitive {p}: attribute {name} refers to accessor {} of {}",
                        index.value(),
                        json.accessors.len()
                    ));
                }
            }
        }
    }
    Ok(())
}

/// A GLB's 12-byte header must count itself (the `gltf` crate subtracts without checking).
fn check_glb_header(bytes: &[u8]) -> Result<(), String> {
    if let Some(header) = bytes.strip_prefix(b"glTF").and_then(|rest| rest.get(4..8)) {
        let length = u32::from_le_bytes(header.try_into().expect("4 bytes"));
        if length < 12 {
            return Err(format!("GLB header: total length {length} is shorter than the 12-byte header"));
        }
    }
    Ok(())
}

/// The buffers' bytes (padded to a multiple of four, as the `gltf` crate does), each at least as
/// long as its declared `byteLength`.
fn load_buffers(
    doc: &gltf::Document,
    mut blob: Option<Vec<u8>>,
    side_files: SideFiles,
) -> Result<Vec<Vec<u8>>, String> {
    let mut buffers = Vec::new();
    for buffer in doc.buffers() {
        let i = buffer.index();
        let mut data = match buffer.source() {
            gltf::buffer::Source::Bin => {
                blob.take().ok_or_else(|| format!("buffer {i} refers to the GLB's BIN chunk, which is missing"))?
            }
            gltf::buffer::Source::Uri(uri) => read_uri(uri, side_files).map_err(|e| format!("buffer {i}: {e}"))?,
        };
        if data.len() < buffer.length() {
            return Err(format!("buffer {i}: expected {} bytes but received {} bytes", buffer.length(), data.len()));
        }
        while data.len() % 4 != 0 {
            data.push(0);
        }
        buffers.push(data);
    }
    Ok(buffers)
}

/// The bytes a URI names: a `data:` URI's base64 payload, or a side file (`file:` or relative,
/// percent-decoded).
fn read_uri(uri: &str, side_files: SideFiles) -> Result<Vec<u8>, String> {
    let shown = || if uri.len() > 80 { format!("{}…", &uri[..uri.floor_char_boundary(80)]) } else { uri.to_string() };
    let name = if let Some(rest) = uri.strip_prefix("data:") {
        let mut parts = rest.split(";base64,");
        let payload = match (parts.next(), parts.next()) {
            (_, Some(payload)) => payload,
            (Some(payload), None) => payload,
            (None, None) => "",
        };
        return base64_decode(payload).ok_or_else(|| format!("'{}': invalid base64 data", shown()));
    } else if let Some(rest) = uri.strip_prefix("file://").or_else(|| uri.strip_prefix("file:")) {
        rest.to_string()
    } else if uri.contains(':') {
        return Err(format!("'{}': unsupported URI scheme", shown()));
    } else {
        percent_decode(uri).ok_or_else(|| format!("'{}': invalid percent-encoding", shown()))?
    };
    side_files(Path::new(&name)).map_err(|e| format!("'{}': {e}", shown()))
}

/// `%XX` escapes decoded (others left as they are); `None` if the result is not UTF-8.
fn percent_decode(s: &str) -> Option<String> {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        let hex = |c: u8| (c as char).to_digit(16);
        match (b[i], b.get(i + 1).copied().and_then(hex), b.get(i + 2).copied().and_then(hex)) {
            (b'%', Some(hi), Some(lo)) => {
                out.push((hi * 16 + lo) as u8);
                i += 3;
            }
            (c, _, _) => {
                out.push(c);
                i += 1;
            }
        }
    }
    String::from_utf8(out).ok()
}

/// Standard base64 (`+/`, padding optional); `None` on any other character.
fn base64_decode(s: &str) -> Option<Vec<u8>> {
    let s = s.trim_end_matches('=');
    let mut out = Vec::with_capacity(s.len() / 4 * 3 + 2);
    let (mut acc, mut bits) = (0u32, 0);
    for c in s.bytes() {
        let v = match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return None,
        };
        acc = (acc << 6) | v as u32;
        bits += 6;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
            acc &= (1 << bits) - 1;
        }
    }
    // One leftover character carries fewer than 8 bits: not base64.
    (bits < 6).then_some(out)
}

/// The bytes of a buffer view, checked against its buffer.
fn view_bytes<'b>(view: &gltf::buffer::View, buffers: &'b [Vec<u8>]) -> Result<&'b [u8], String> {
    let data = &buffers[view.buffer().index()];
    view.offset().checked_add(view.length()).and_then(|end| data.get(view.offset()..end)).ok_or_else(|| {
        format!(
            "buffer view {} ({} bytes at offset {}) overruns buffer {} ({} bytes)",
            view.index(),
            view.length(),
            view.offset(),
            view.buffer().index(),
            data.len()
        )
    })
}

/// `count` elements of `size` bytes from `offset` in `view` (its stride, else tightly packed),
/// after checking that they lie inside it.
fn strided<'b>(
    what: &str,
    view: &gltf::buffer::View,
    offset: usize,
    count: usize,
    size: usize,
    buffers: &'b [Vec<u8>],
) -> Result<impl Iterator<Item = &'b [u8]> + use<'b>, String> {
    let data = view_bytes(view, buffers)?;
    let stride = view.stride().unwrap_or(size);
    if stride < size {
        return Err(format!("{what}: byteStride {stride} is smaller than its {size}-byte elements"));
    }
    let end = count
        .checked_sub(1)
        .and_then(|last| last.checked_mul(stride))
        .and_then(|n| n.checked_add(offset))
        .and_then(|n| n.checked_add(size))
        .filter(|&end| end <= data.len())
        .ok_or_else(|| {
            format!(
                "{what}: {count} elements of {size} bytes (stride {stride}) at offset {offset} overrun buffer view {} ({} bytes)",
                view.index(),
                data.len()
            )
        })?;
    let data = &data[offset..end];
    Ok((0..count).map(move |k| &data[k * stride..k * stride + size]))
}

/// Read accessor `a` (dense, sparse, or neither = zeros) as elements of `size` bytes, each
/// decoded by `decode`. The count is checked against the bytes present before anything is
/// allocated: an accessor without a buffer view may not claim more elements than the file's
/// buffers have bytes.
fn read_accessor<T: Clone>(
    a: &gltf::Accessor,
    size: usize,
    buffers: &[Vec<u8>],
    zero: T,
    decode: impl Fn(&[u8]) -> T,
) -> Result<Vec<T>, String> {
    let what = format!("accessor {}", a.index());
    let count = a.count();
    if count == 0 {
        return Err(format!("{what} has count 0"));
    }
    let mut out = match a.view() {
        Some(view) => strided(&what, &view, a.offset(), count, size, buffers)?.map(&decode).collect(),
        None => {
            let present: usize = buffers.iter().map(Vec::len).sum();
            if count > present {
                return Err(format!(
                    "{what} claims {count} elements without a buffer view, more than the {present} bytes of buffers"
                ));
            }
            vec![zero; count]
        }
    };
    if let Some(sparse) = a.sparse() {
        let n = sparse.count();
        if n == 0 || n > count {
            return Err(format!("{what}: sparse count {n} is not in 1..={count}"));
        }
        let indices = sparse.indices();
        let index_size = indices.index_type().size();
        let index_bytes =
            strided(&format!("{what} sparse indices"), &indices.view(), indices.offset(), n, index_size, buffers)?;
        let values = sparse.values();
        let value_bytes = strided(&format!("{what} sparse values"), &values.view(), values.offset(), n, size, buffers)?;
        for (i, v) in index_bytes.zip(value_bytes) {
            let i = i.iter().rev().fold(0usize, |acc, &b| (acc << 8) | b as usize);
            let slot = out.get_mut(i).ok_or_else(|| format!("{what}: sparse index {i} is not below {count}"))?;
            *slot = decode(v);
        }
    }
    Ok(out)
}

fn f32_at(b: &[u8], k: usize) -> f32 {
    f32::from_le_bytes(b[4 * k..4 * k + 4].try_into().expect("4 bytes"))
}

fn add_primitive(scene: &mut Scene, prim: &gltf::Primitive, buffers: &[Vec<u8>], world: Mat4) -> Result<(), String> {
    if prim.mode() != gltf::mesh::Mode::Triangles {
        return Ok(()); // points and lines have no surface to occlude
    }
    let a = prim.get(&gltf::Semantic::Positions).ok_or("a triangle primitive has no POSITION")?;
    if (a.data_type(), a.dimensions()) != (DataType::F32, Dimensions::Vec3) {
        return Err(format!("POSITION accessor {} is not VEC3 of FLOAT", a.index()));
    }
    let mut positions: Vec<Vec3> =
        read_accessor(&a, 12, buffers, Vec3::ZERO, |b| Vec3::new(f32_at(b, 0), f32_at(b, 1), f32_at(b, 2)))?;
    for p in &mut positions {
        *p = world.transform_point3(*p);
    }
    let uvs: Vec<Vec2> = match prim.get(&gltf::Semantic::TexCoords(0)) {
        Some(t) => {
            if t.dimensions() != Dimensions::Vec2 {
                return Err(format!("TEXCOORD_0 accessor {} is not VEC2", t.index()));
            }
            match t.data_type() {
                DataType::F32 => read_accessor(&t, 8, buffers, Vec2::ZERO, |b| Vec2::new(f32_at(b, 0), f32_at(b, 1)))?,
                DataType::U8 => {
                    read_accessor(&t, 2, buffers, Vec2::ZERO, |b| Vec2::new(b[0] as f32 / 255.0, b[1] as f32 / 255.0))?
                }
                DataType::U16 => read_accessor(&t, 4, buffers, Vec2::ZERO, |b| {
                    let c = |k: usize| u16::from_le_bytes([b[2 * k], b[2 * k + 1]]) as f32 / 65535.0;
                    Vec2::new(c(0), c(1))
                })?,
                other => return Err(format!("TEXCOORD_0 accessor {} has component type {other:?}", t.index())),
            }
        }
        None => vec![Vec2::ZERO; positions.len()],
    };
    let indices: Vec<u32> = match prim.indices() {
        Some(i) => {
            if i.dimensions() != Dimensions::Scalar {
                return Err(format!("index accessor {} is not SCALAR", i.index()));
            }
            match i.data_type() {
                DataType::U8 => read_accessor(&i, 1, buffers, 0, |b| b[0] as u32)?,
                DataType::U16 => read_accessor(&i, 2, buffers, 0, |b| u16::from_le_bytes([b[0], b[1]]) as u32)?,
                DataType::U32 => {
                    read_accessor(&i, 4, buffers, 0, |b| u32::from_le_bytes(b.try_into().expect("4 bytes")))?
                }
                other => return Err(format!("index accessor {} has component type {other:?}", i.index())),
            }
        }
        None => (0..positions.len() as u32).collect(),
    };
    let material = prim.material().index().map_or(0, |m| m as u32);
    for tri in indices.chunks_exact(3) {
        let mut corners = [Vec3::ZERO; 3];
        let mut tex = [Vec2::ZERO; 3];
        for k in 0..3 {
            let i = tri[k] as usize;
            if i >= positions.len() {
                return Err(format!("index {i} out of {} vertices", positions.len()));
            }
            corners[k] = positions[i];
            tex[k] = uvs.get(i).copied().unwrap_or(Vec2::ZERO);
        }
        scene.triangles.push(corners);
        scene.triangle_materials.push(material);
        scene.triangle_uvs.push(tex);
    }
    Ok(())
}

fn material(
    m: &gltf::Material,
    doc: &gltf::Document,
    buffers: &[Vec<u8>],
    side_files: SideFiles,
) -> Result<Material, String> {
    let name = m.name().unwrap_or_default().to_string();
    if m.alpha_mode() != gltf::material::AlphaMode::Mask {
        return Ok(Material { name, alpha_mask: None });
    }
    let pbr = m.pbr_metallic_roughness();
    let factor = pbr.base_color_factor()[3];
    let cutoff = m.alpha_cutoff().unwrap_or(0.5);
    let Some(texture) = pbr.base_color_texture() else {
        return Ok(Material { name, alpha_mask: None });
    };
    let image = texture.texture().source().index();
    let img = decode_image(doc, image, buffers, side_files).map_err(|e| format!("image {image}: {e}"))?;
    let (width, height) = (img.width(), img.height());
    // Only 8-bit RGBA carries alpha here (as before); other layouts are opaque times the factor.
    let alpha = match img {
        image::DynamicImage::ImageRgba8(rgba) => rgba.pixels().map(|p| factor * p[3] as f32 / 255.0).collect(),
        _ => vec![factor; width as usize * height as usize],
    };
    Ok(Material { name, alpha_mask: Some(AlphaMask { width, height, alpha, cutoff }) })
}

/// Decode a PNG or JPEG image of the document, with the decoder's allocation bounded by the
/// encoded size (no real PNG or JPEG expands by more than ~1100×).
fn decode_image(
    doc: &gltf::Document,
    index: usize,
    buffers: &[Vec<u8>],
    side_files: SideFiles,
) -> Result<image::DynamicImage, String> {
    use image::ImageFormat;
    let by_mime = |mime: &str| match mime {
        "image/png" => Some(ImageFormat::Png),
        "image/jpeg" => Some(ImageFormat::Jpeg),
        _ => None,
    };
    // From the JSON, not `Image::source()`: that unwraps a missing `mimeType` or `uri`.
    let json = doc.as_json().images.get(index).ok_or("it does not exist")?;
    let mime_type = json.mime_type.as_ref().map(|m| m.0.as_str());
    let (bytes, format): (std::borrow::Cow<[u8]>, Option<ImageFormat>) = match (&json.buffer_view, &json.uri) {
        (Some(view), _) => {
            let view = doc.views().nth(view.value()).ok_or("its bufferView does not exist")?;
            (view_bytes(&view, buffers)?.into(), mime_type.and_then(by_mime))
        }
        (None, Some(uri)) => {
            let format = match (uri.strip_prefix("data:"), mime_type) {
                (Some(rest), _) => rest.split(";base64,").next().and_then(by_mime),
                (None, Some(mime)) => by_mime(mime),
                (None, None) => match uri.rsplit('.').next() {
                    Some("png") => Some(ImageFormat::Png),
                    Some("jpg" | "jpeg") => Some(ImageFormat::Jpeg),
                    _ => None,
                },
            };
            (read_uri(uri, side_files)?.into(), format)
        }
        (None, None) => return Err("it has neither a bufferView nor a uri".into()),
    };
    let format = match format.or_else(|| image::guess_format(&bytes).ok()) {
        Some(f @ (ImageFormat::Png | ImageFormat::Jpeg)) => f,
        _ => return Err("unsupported image encoding (PNG and JPEG are read)".into()),
    };
    let mut limits = image::Limits::default();
    limits.max_alloc = Some((bytes.len() as u64).saturating_mul(2048).saturating_add(1 << 20).min(512 << 20));
    let mut reader = image::ImageReader::with_format(std::io::Cursor::new(&bytes[..]), format);
    reader.limits(limits);
    reader.decode().map_err(|e| e.to_string())
}
