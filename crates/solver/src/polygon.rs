//! Area and centroid of plane polygons (the shoelace formula), for slices and voussoirs.

/// Signed area (positive counter-clockwise) and centroid of a simple polygon. Coordinates are
/// taken relative to the first vertex, which keeps the cross products well conditioned far from
/// the origin. A polygon of zero area has its first vertex as centroid.
pub(crate) fn polygon_area_centroid(polygon: &[(f64, f64)]) -> (f64, (f64, f64)) {
    let n = polygon.len();
    let (ox, oy) = polygon[0];
    let (mut twice_area, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let (x0, y0) = (polygon[i].0 - ox, polygon[i].1 - oy);
        let (x1, y1) = (polygon[(i + 1) % n].0 - ox, polygon[(i + 1) % n].1 - oy);
        let cross = x0 * y1 - x1 * y0;
        twice_area += cross;
        cx += (x0 + x1) * cross;
        cy += (y0 + y1) * cross;
    }
    if twice_area == 0.0 {
        return (0.0, polygon[0]);
    }
    let area = 0.5 * twice_area;
    (area, (ox + cx / (6.0 * area), oy + cy / (6.0 * area)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rectangle_and_triangle_by_hand() {
        let (a, c) = polygon_area_centroid(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)]);
        assert_eq!((a, c), (2.0, (1.0, 0.5)));
        // Clockwise: negative area, same centroid; a triangle's centroid is its vertex mean.
        let (a, c) = polygon_area_centroid(&[(1e6, 1e6), (1e6, 1e6 + 3.0), (1e6 + 3.0, 1e6)]);
        assert_eq!(a, -4.5);
        assert!((c.0 - (1e6 + 1.0)).abs() < 1e-9 && (c.1 - (1e6 + 1.0)).abs() < 1e-9);
    }
}
