//! The structure of an arch request: four named geometry objects told apart by `kind` (an
//! OpenAPI discriminator), the circular one shared by every arch route. Read by hand so that an
//! error inside names its full path (`geometry.blocks[3].corners`), which serde's internally
//! tagged enums lose.

use serde::de::{DeserializeOwned, Error as _};
use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;
use utoipa::ToSchema;

use super::assembly::{PolygonDto, RingJointsDto};
use crate::extract::json_kind;

/// Shape of the voussoirs of a circular arch.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum VoussoirDto {
    /// Annular sectors (curved intrados and extrados; exact centroid).
    #[default]
    Curved,
    /// Straight intrados and extrados between the corners (polygon centroid).
    Quadrilateral,
}

/// `kind` of a circular arch.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum CircularKind {
    /// The circular arch generator.
    Circular,
}

/// `kind` of an arch given by its intrados profile.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ProfileKind {
    /// An intrados of a named shape, or measured.
    Profile,
}

/// The shape of an intrados (model §10).
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ProfileShapeDto {
    /// A circular arc through both springings and the crown; rise < span/2.
    Segmental,
    /// A half circle; rise = span/2 (may be left out).
    Semicircular,
    /// The half ellipse of semi-axes span/2 and rise.
    Elliptical,
    /// Haunch arcs of `haunch_radius` centred on the springing line, tangent to a crown arc
    /// centred on the vertical through the crown; 0 < haunch_radius < rise < span/2.
    ThreeCentred,
    /// Two arcs centred on the springing line, each through its springing and the crown; rise
    /// > span/2, or `radius` > span/2 instead of the rise (radius = span: equilateral).
    Pointed,
    /// y = rise·(1 − (2x/span)²).
    Parabolic,
    /// The catenary through both springings and the crown.
    Catenary,
    /// A measured intrados: the polyline through `intrados`.
    Points,
}

/// An arch by its intrados (model §10): span and rise of the intrados, springings at
/// (±span/2, 0), joints normal to the intrados at equal arc lengths along it, the extrados at
/// `thickness` along those normals. Blocks are numbered from the right springing (x = span/2),
/// ring by ring. `shape: points` takes a measured intrados instead of span and rise.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ProfileGeometryDto {
    /// Always `profile`.
    pub kind: ProfileKind,
    /// The intrados' shape.
    pub shape: ProfileShapeDto,
    /// Span between the intrados springings, 1e-9 ≤ span ≤ 1e9 (not with `points`).
    #[serde(default)]
    #[schema(examples(10.0))]
    pub span: Option<f64>,
    /// Rise of the intrados crown above the springings, 1e-3·span ≤ rise ≤ 100·span, within
    /// what the shape allows (not with `points`; optional for `semicircular`; `pointed` takes
    /// it or `radius`).
    #[serde(default)]
    #[schema(examples(2.5))]
    pub rise: Option<f64>,
    /// `pointed` only: the radius of its two arcs, > span/2, instead of the rise.
    #[serde(default)]
    pub radius: Option<f64>,
    /// `three_centred` only: the radius of the haunch arcs, 0 < haunch_radius < rise.
    #[serde(default)]
    pub haunch_radius: Option<f64>,
    /// `points` only: the measured intrados, 3 to 10000 points [x, y] with x running one way,
    /// rising to one crown above both springings and falling after it.
    #[serde(default)]
    pub intrados: Option<Vec<[f64; 2]>>,
    /// Thickness along the joints, 0 < thickness < span. Required by the dead- and live-load
    /// routes; the minimum-thickness route finds it.
    #[serde(default)]
    #[schema(examples(0.6))]
    pub thickness: Option<f64>,
    /// Voussoirs per ring N, 1 ≤ N ≤ 10000.
    #[schema(examples(40))]
    #[serde(deserialize_with = "crate::nullable::integer")]
    pub voussoirs: usize,
    /// Rings the thickness is split into, 1 ≤ rings ≤ 16, as for `circular`. Defaults to 1.
    #[serde(default = "one", deserialize_with = "crate::nullable::integer_or_one")]
    #[schema(nullable)]
    pub rings: usize,
    /// How the joints of neighbouring rings lie. Defaults to `staggered`.
    #[serde(default, deserialize_with = "crate::nullable::name_or_default")]
    #[schema(nullable)]
    pub ring_joints: RingJointsDto,
    /// Spans on piers, 1 ≤ spans ≤ 20, as for `circular`. Defaults to 1.
    #[serde(default = "one", deserialize_with = "crate::nullable::integer_or_one")]
    #[schema(nullable)]
    pub spans: usize,
    /// With `spans` > 1: each pier's width between the intrados springings of its two spans.
    #[serde(default)]
    pub pier_width: Option<f64>,
    /// With `spans` > 1: each pier's height below its lower springing, > 0.
    #[serde(default)]
    pub pier_height: Option<f64>,
}

/// `kind` of a chain of quadrilateral blocks.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum BlocksKind {
    /// A chain of quadrilaterals.
    Blocks,
}

/// `kind` of an assembly of polygons.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum AssemblyKind {
    /// Polygonal blocks on supports.
    Assembly,
}

/// Circular arch (model §1.3): centre at the origin, from polar angle C (right springing) to
/// 180° − B (left springing), N voussoirs of equal angle. The one circular geometry of every
/// arch route.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CircularGeometryDto {
    /// Always `circular`.
    pub kind: CircularKind,
    /// Middle radius R, 1e-9 ≤ R ≤ 1e9.
    #[schema(examples(10.0))]
    pub radius: f64,
    /// Voussoir thickness D, 0 < D < 2R. Required by the dead- and live-load routes. On the
    /// minimum-thickness route optional: given, the answer adds the geometric factor of safety
    /// D / D_min.
    #[serde(default)]
    #[schema(examples(1.0748))]
    pub thickness: Option<f64>,
    /// Number of voussoirs N, 1 ≤ N ≤ 10000.
    #[schema(examples(1800))]
    #[serde(deserialize_with = "crate::nullable::integer")]
    pub voussoirs: usize,
    /// Left base angle B in degrees, −90 < B < 90 (0: semicircle; > 0 segmental; < 0
    /// horseshoe). Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(examples(0.0))]
    pub left_base_angle_deg: f64,
    /// Right base angle C in degrees, −90 < C < 90. Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(examples(0.0))]
    pub right_base_angle_deg: f64,
    /// Voussoir shape. Defaults to `curved`.
    #[serde(default, deserialize_with = "crate::nullable::name_or_default")]
    #[schema(nullable)]
    pub voussoir: VoussoirDto,
    /// Rings the thickness is split into, 1 ≤ rings ≤ 16 (ring 1 innermost; blocks are
    /// numbered ring by ring). More than one makes the arch an assembly of polygonal
    /// voussoirs, solved on the general formulation. Not on the minimum-thickness route.
    /// Defaults to 1.
    #[serde(default = "one", deserialize_with = "crate::nullable::integer_or_one")]
    #[schema(nullable)]
    pub rings: usize,
    /// How the joints of neighbouring rings lie. Defaults to `staggered`.
    #[serde(default, deserialize_with = "crate::nullable::name_or_default")]
    #[schema(nullable)]
    pub ring_joints: RingJointsDto,
    /// Spans, 1 ≤ spans ≤ 20: the arch repeated on piers (`pier_width`, `pier_height`). Not
    /// on the minimum-thickness route. Defaults to 1.
    #[serde(default = "one", deserialize_with = "crate::nullable::integer_or_one")]
    #[schema(nullable)]
    pub spans: usize,
    /// With `spans` > 1: each pier's width between the intrados springings of its two spans
    /// (more than D·(cos B + cos C), so the springings do not overlap).
    #[serde(default)]
    pub pier_width: Option<f64>,
    /// With `spans` > 1: each pier's height below its lower springing, > 0.
    #[serde(default)]
    pub pier_height: Option<f64>,
}

impl CircularGeometryDto {
    /// One ring, one span, curved voussoirs: the thesis' arch, whose extrados is an arc.
    pub fn is_curved_single(&self) -> bool {
        self.voussoir == VoussoirDto::Curved && self.rings == 1 && self.spans == 1
    }
}

fn one() -> usize {
    1
}

/// One block of an explicit chain.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct BlockCornersDto {
    /// Corners [x, y] in the order intrados-start, extrados-start, extrados-end, intrados-end;
    /// a block's start face is the previous block's end face.
    #[schema(schema_with = corners_schema)]
    pub corners: [[f64; 2]; 4],
}

/// Four [x, y] points.
fn corners_schema() -> utoipa::openapi::schema::Array {
    use utoipa::openapi::schema::{ArrayBuilder, ObjectBuilder, Type};
    let point = ArrayBuilder::new()
        .items(
            ObjectBuilder::new()
                .schema_type(Type::Number)
                .minimum(Some(-crate::limits::MAX_LENGTH))
                .maximum(Some(crate::limits::MAX_LENGTH)),
        )
        .min_items(Some(2))
        .max_items(Some(2));
    ArrayBuilder::new()
        .items(point)
        .min_items(Some(4))
        .max_items(Some(4))
        .description(Some(
            "Corners [x, y]: intrados-start, extrados-start, extrados-end, intrados-end",
        ))
        .examples([serde_json::json!([
            [9.5, 0.0],
            [10.5, 0.0],
            [10.5, 1.0],
            [9.5, 1.0]
        ])])
        .build()
}

/// A chain of quadrilateral blocks; the first block's start face and the last block's end face
/// rest on supports.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct BlocksGeometryDto {
    /// Always `blocks`.
    pub kind: BlocksKind,
    /// The blocks, 1 to 10000 of them, in order.
    pub blocks: Vec<BlockCornersDto>,
}

/// Any polygonal blocks on fixed supports (model §5.4): contacts are found where edges of two
/// blocks, or of a block and a support, run along each other.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct AssemblyGeometryDto {
    /// Always `assembly`.
    pub kind: AssemblyKind,
    /// The blocks, 1 to 10000 of them.
    pub blocks: Vec<PolygonDto>,
    /// The fixed supports, 1 to 1000 of them.
    pub supports: Vec<PolygonDto>,
}

/// The structure, by `kind`: the thesis' circular arch (`circular`), an arch by its intrados
/// profile (`profile`), any chain of quadrilateral blocks (`blocks`), or any polygons on
/// supports (`assembly`).
#[derive(Debug, Clone, Serialize, ToSchema)]
#[serde(untagged)]
#[schema(discriminator(property_name = "kind", mapping(
    ("circular" = "#/components/schemas/CircularGeometryDto"),
    ("blocks" = "#/components/schemas/BlocksGeometryDto"),
    ("assembly" = "#/components/schemas/AssemblyGeometryDto"),
    ("profile" = "#/components/schemas/ProfileGeometryDto"),
)))]
pub enum GeometryDto {
    /// `kind: circular`.
    Circular(CircularGeometryDto),
    /// `kind: blocks`.
    Blocks(BlocksGeometryDto),
    /// `kind: assembly`.
    Assembly(AssemblyGeometryDto),
    /// `kind: profile`.
    Profile(ProfileGeometryDto),
}

impl<'de> Deserialize<'de> for GeometryDto {
    /// By `kind`, each variant read with the path of its errors kept (`blocks[3].corners: …`),
    /// which the request's error joins to `geometry`.
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let value = Value::deserialize(deserializer)?;
        let Value::Object(map) = &value else {
            return Err(D::Error::custom(format!(
                "invalid type: {}, expected an object with `kind`",
                json_kind(&value)
            )));
        };
        match map.get("kind") {
            None => Err(D::Error::missing_field("kind")),
            Some(Value::String(kind)) => match kind.as_str() {
                "circular" => variant(&value).map(Self::Circular),
                "blocks" => variant(&value).map(Self::Blocks),
                "assembly" => variant(&value).map(Self::Assembly),
                "profile" => variant(&value).map(Self::Profile),
                other => Err(D::Error::custom(format!(
                    "kind: unknown variant `{other}`, expected one of `circular`, `profile`, \
                     `blocks`, `assembly`"
                ))),
            },
            Some(other) => Err(D::Error::custom(format!(
                "kind: invalid type: {}, expected one of `circular`, `profile`, `blocks`, \
                 `assembly`",
                json_kind(other)
            ))),
        }
    }
}

/// A geometry object read as `T`, an error prefixed with its path inside the object.
pub(crate) fn variant<T: DeserializeOwned, E: serde::de::Error>(value: &Value) -> Result<T, E> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        if path.is_empty() || path == "." {
            E::custom(e.into_inner())
        } else {
            E::custom(format!("{path}: {}", e.into_inner()))
        }
    })
}
