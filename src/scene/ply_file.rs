//! PLY (ascii or binary, optionally gzip-compressed) through `ply-rs`: `vertex` elements with
//! x/y/z and `face` elements with a `vertex_indices` (or `vertex_index`) list; polygons are
//! fanned into triangles.
//!
//! The header is read first and every element count is checked against the bytes that follow
//! it (each element takes at least a byte, a binary one at least the size of its scalars), so a
//! header claiming 10¹⁰ vertices is an error before anything is read or allocated for them. The
//! elements are then read one at a time into compact rows (three coordinates, one index list)
//! instead of a map per element.

use super::{Scene, SceneError};
use aokit_shaders::glam::Vec3;
use ply_rs::parser::Parser;
use ply_rs::ply::{ElementDef, Encoding, Header, Property, PropertyAccess, PropertyType, ScalarType};
use std::io::{BufRead, Read};
use std::path::Path;

fn scalar(p: &Property) -> Option<f64> {
    Some(match *p {
        Property::Char(v) => v as f64,
        Property::UChar(v) => v as f64,
        Property::Short(v) => v as f64,
        Property::UShort(v) => v as f64,
        Property::Int(v) => v as f64,
        Property::UInt(v) => v as f64,
        Property::Float(v) => v as f64,
        Property::Double(v) => v,
        _ => return None,
    })
}

fn index_list(p: Property) -> Option<Vec<i64>> {
    Some(match p {
        Property::ListChar(v) => v.into_iter().map(i64::from).collect(),
        Property::ListUChar(v) => v.into_iter().map(i64::from).collect(),
        Property::ListShort(v) => v.into_iter().map(i64::from).collect(),
        Property::ListUShort(v) => v.into_iter().map(i64::from).collect(),
        Property::ListInt(v) => v.into_iter().map(i64::from).collect(),
        Property::ListUInt(v) => v.into_iter().map(i64::from).collect(),
        _ => return None,
    })
}

/// A `vertex` row: its x, y, z.
#[derive(Default)]
struct VertexRow([Option<f64>; 3]);

impl PropertyAccess for VertexRow {
    fn new() -> Self {
        VertexRow::default()
    }
    fn set_property(&mut self, name: String, property: Property) {
        let k = match name.as_str() {
            "x" => 0,
            "y" => 1,
            "z" => 2,
            _ => return,
        };
        self.0[k] = scalar(&property);
    }
}

/// A `face` row: its vertex index list (`vertex_indices`, else `vertex_index`).
#[derive(Default)]
struct FaceRow {
    indices: Option<Vec<i64>>,
    index: Option<Vec<i64>>,
}

impl PropertyAccess for FaceRow {
    fn new() -> Self {
        FaceRow::default()
    }
    fn set_property(&mut self, name: String, property: Property) {
        match name.as_str() {
            "vertex_indices" => self.indices = index_list(property),
            "vertex_index" => self.index = index_list(property),
            _ => {}
        }
    }
}

/// Any other element: read (to get past it) and dropped.
struct SkipRow;

impl PropertyAccess for SkipRow {
    fn new() -> Self {
        SkipRow
    }
}

pub(super) fn load_gz_bytes(path: &Path, bytes: &[u8]) -> Result<Scene, SceneError> {
    let mut out = Vec::new();
    flate2::read::GzDecoder::new(bytes).read_to_end(&mut out).map_err(|e| SceneError::malformed(path, "gzip", e))?;
    load_bytes(path, &out)
}

fn size_of(t: &ScalarType) -> usize {
    match t {
        ScalarType::Char | ScalarType::UChar => 1,
        ScalarType::Short | ScalarType::UShort => 2,
        ScalarType::Int | ScalarType::UInt | ScalarType::Float => 4,
        ScalarType::Double => 8,
    }
}

/// The fewest bytes one element of `def` takes: binary, its scalars and list counts; ascii, a
/// character and a separator per property; at least one byte either way.
fn min_element_bytes(def: &ElementDef, encoding: &Encoding) -> usize {
    let bytes: usize = def
        .properties
        .values()
        .map(|p| match (&p.data_type, encoding) {
            (_, Encoding::Ascii) => 2,
            (PropertyType::Scalar(t), _) => size_of(t),
            (PropertyType::List(count, _), _) => size_of(count),
        })
        .sum();
    bytes.max(1)
}

/// Which property of a face row holds the indices: `vertex_indices` if the element has one (even
/// of the wrong type, as before), else `vertex_index`.
fn face_list_name(def: &ElementDef) -> &'static str {
    if def.properties.contains_key("vertex_indices") { "vertex_indices" } else { "vertex_index" }
}

fn is_integer_list(def: &ElementDef, name: &str) -> bool {
    matches!(
        def.properties.get(name).map(|p| &p.data_type),
        Some(PropertyType::List(
            _,
            ScalarType::Char
                | ScalarType::UChar
                | ScalarType::Short
                | ScalarType::UShort
                | ScalarType::Int
                | ScalarType::UInt
        ))
    )
}

fn is_scalar(def: &ElementDef, name: &str) -> bool {
    matches!(def.properties.get(name).map(|p| &p.data_type), Some(PropertyType::Scalar(_)))
}

/// Reads the rows of one element, whatever the encoding.
struct Rows<'a, 'b> {
    reader: &'a mut &'b [u8],
    header: &'a Header,
    /// Line number of the next ascii row.
    line: usize,
}

impl Rows<'_, '_> {
    fn read<E: PropertyAccess>(&mut self, def: &ElementDef, mut each: impl FnMut(E)) -> Result<(), String> {
        let parser = Parser::<E>::new();
        let mut text = String::new();
        for i in 0..def.count {
            let row = match self.header.encoding {
                Encoding::Ascii => {
                    text.clear();
                    self.reader.read_line(&mut text).map_err(|e| format!("line {}: {e}", self.line))?;
                    if text.is_empty() {
                        return Err(format!(
                            "the file ends after {i} of {} '{}' elements (line {})",
                            def.count, def.name, self.line
                        ));
                    }
                    let row = parser
                        .read_ascii_element(&text, def)
                        .map_err(|e| format!("line {}: {}", self.line, ply_message(&e)));
                    self.line += 1;
                    row?
                }
                Encoding::BinaryLittleEndian => {
                    parser.read_little_endian_element(self.reader, def).map_err(|e| binary_error(def, i, &e))?
                }
                Encoding::BinaryBigEndian => {
                    parser.read_big_endian_element(self.reader, def).map_err(|e| binary_error(def, i, &e))?
                }
            };
            each(row);
        }
        Ok(())
    }
}

/// A ply-rs message without its Debug dump: its first line and the text it could not read
/// ("Line 3: Couldn't parse line.\n\tString: 'elemnt x 3\n'\n\tError: ParseError { … }" becomes
/// "Line 3: Couldn't parse line: 'elemnt x 3'").
fn ply_message(e: &std::io::Error) -> String {
    let text = e.to_string();
    let first = text.lines().next().unwrap_or_default().trim().trim_end_matches(['.', ',', ' ']);
    let quoted = ["String: '", "Value: '"].iter().find_map(|key| {
        let rest = &text[text.find(key)? + key.len()..];
        let rest = &rest[..rest.find("\n\tError").unwrap_or(rest.len())];
        let rest = rest.trim_end();
        Some(rest.strip_suffix('\'').unwrap_or(rest).trim().to_string())
    });
    match quoted {
        Some(q) if q.chars().count() > 80 => format!("{first}: '{}…'", q.chars().take(80).collect::<String>()),
        Some(q) => format!("{first}: '{q}'"),
        None => first.to_string(),
    }
}

/// A binary read error without ply-rs's Debug dump: almost always the data running out.
fn binary_error(def: &ElementDef, i: usize, e: &std::io::Error) -> String {
    let text = e.to_string();
    if e.kind() == std::io::ErrorKind::UnexpectedEof || text.contains("UnexpectedEof") {
        format!("the data ends inside '{}' element {i} of {} (truncated file, or a wrong header)", def.name, def.count)
    } else {
        format!("'{}' element {i} of {}: {}", def.name, def.count, ply_message(e))
    }
}

/// ply-rs's header grammar parses the element counts and the version with `unwrap()`: a number
/// beyond u64 in an `element` or `format` line would panic, so it is refused here first.
fn check_header_numbers(bytes: &[u8]) -> Result<(), String> {
    for (n, line) in bytes.split(|&b| b == b'\n').enumerate() {
        if line.starts_with(b"end_header") {
            break;
        }
        if !(line.starts_with(b"element") || line.starts_with(b"format")) {
            continue;
        }
        let mut i = 0;
        while i < line.len() {
            let run = line[i..].iter().take_while(|b| b.is_ascii_digit()).count();
            let after_separator = i > 0 && matches!(line[i - 1], b' ' | b'\t' | b'.');
            if run > 0
                && after_separator
                && std::str::from_utf8(&line[i..i + run]).ok().and_then(|d| d.parse::<u64>().ok()).is_none()
            {
                let digits = String::from_utf8_lossy(&line[i..i + run.min(40)]).into_owned();
                return Err(format!("header line {}: the number {digits} is too large", n + 1));
            }
            i += run.max(1);
        }
    }
    Ok(())
}

/// Parse PLY bytes; `path` names the file in errors.
pub(super) fn load_bytes(path: &Path, bytes: &[u8]) -> Result<Scene, SceneError> {
    let bad = |problem: String| SceneError::malformed(path, "PLY", problem);
    check_header_numbers(bytes).map_err(bad)?;
    let mut reader = bytes;
    let header =
        Parser::<SkipRow>::new().read_header(&mut reader).map_err(|e| bad(format!("header: {}", ply_message(&e))))?;
    let header_bytes = bytes.len() - reader.len();

    // Every count against the bytes that follow the header, before reading anything.
    let mut needed: u128 = 0;
    for def in header.elements.values() {
        let element = min_element_bytes(def, &header.encoding) as u128;
        needed += def.count as u128 * element;
        // An ascii file may lack the last line break.
        if needed > reader.len() as u128 + 1 {
            return Err(bad(format!(
                "the header declares {} '{}' elements, at least {} bytes, but only {} bytes follow it",
                def.count,
                def.name,
                def.count as u128 * element,
                reader.len()
            )));
        }
    }
    let vertex = header.elements.get("vertex").ok_or_else(|| bad("no 'vertex' element".into()))?;
    if vertex.count > 0 {
        for k in ["x", "y", "z"] {
            if !is_scalar(vertex, k) {
                return Err(bad(format!("the 'vertex' element has no scalar property '{k}'")));
            }
        }
    }
    let face = header.elements.get("face").ok_or_else(|| bad("no 'face' element".into()))?;
    let list = face_list_name(face);
    if face.count > 0 && !is_integer_list(face, list) {
        return Err(bad(format!("the 'face' element has no integer list '{list}'")));
    }

    let mut positions: Vec<Vec3> = Vec::new();
    // All faces' indices, and where each face's end.
    let mut indices: Vec<i64> = Vec::new();
    let mut face_ends: Vec<usize> = Vec::new();
    let line = bytes[..header_bytes].iter().filter(|&&b| b == b'\n').count() + 1;
    let mut rows = Rows { reader: &mut reader, header: &header, line };
    for (name, def) in &header.elements {
        match name.as_str() {
            "vertex" => rows.read(def, |v: VertexRow| {
                let [x, y, z] = v.0.map(|c| c.unwrap_or(f64::NAN) as f32);
                positions.push(Vec3::new(x, y, z));
            }),
            "face" => rows.read(def, |f: FaceRow| {
                let list = if list == "vertex_indices" { f.indices } else { f.index };
                indices.extend(list.unwrap_or_default());
                face_ends.push(indices.len());
            }),
            _ => rows.read(def, |_: SkipRow| {}),
        }
        .map_err(bad)?;
    }

    let mut scene = Scene { name: path.display().to_string(), ..Default::default() };
    let mut start = 0;
    for (f, &end) in face_ends.iter().enumerate() {
        let list = &indices[start..end];
        start = end;
        let vertex = |i: i64| {
            usize::try_from(i)
                .ok()
                .and_then(|i| positions.get(i).copied())
                .ok_or_else(|| bad(format!("face {f} refers to vertex {i} of {}", positions.len())))
        };
        for k in 2..list.len() {
            scene.triangles.push([vertex(list[0])?, vertex(list[k - 1])?, vertex(list[k])?]);
        }
    }
    Ok(scene)
}
