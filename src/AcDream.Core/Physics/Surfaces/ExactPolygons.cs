using System.Numerics;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>
/// An object's polygons as a cast meets them: the same walls and floor triangles the movers meet, but each vertex placed
/// in double precision from the model's float vertices and the placement's float frame (landblock-local metres). A
/// placed vertex rounded to a float is off by up to half its spacing (7.6e-6 m near 150 m), which a path meeting the
/// surface at a grazing angle turns into a long error along it (4.4e-4 m at 1°); these are off by rounding of double.
/// </summary>
internal sealed class ExactPolygons
{
    /// <summary>No polygons.</summary>
    public static readonly ExactPolygons None = new([], []);

    private ExactPolygons(D3[] walls, D3[] floors) => (Walls, Floors) = (walls, floors);

    /// <summary>The wall polygons' vertices, by the index of <see cref="CellWalls.Vertices"/> (a polygon's are <c>First</c> to <c>First + Count − 1</c>).</summary>
    public D3[] Walls { get; }

    /// <summary>
    /// Each floor triangle's three corners, in the order of the floors (triangle i's at 3i, 3i + 1, 3i + 2): on its
    /// polygon's plane (the Newell normal of the exact vertices, through their mean) when the polygon is planar, as the
    /// floor's Z is (<see cref="FloorPlane.OfPolygon"/>); else its own exact vertices.
    /// </summary>
    public D3[] Floors { get; }

    /// <summary>
    /// The exact walls and floors of <paramref name="polygons"/> (placed in floats, each with its winding normal, as
    /// <see cref="CellWalls.Build"/> and <see cref="CellSurface.BuildFloors"/> were given them; no portals) from
    /// <paramref name="exact"/> (the same polygons placed in double), chosen as those two choose.
    /// </summary>
    /// <exception cref="InvalidOperationException">The choice differs from <paramref name="walls"/> or <paramref name="floors"/> (a fault of the engine).</exception>
    public static ExactPolygons Build(List<(ushort Id, Vector3[] Vertices, Vector3 Normal)> polygons, List<D3[]> exact, CellWalls walls, ReadOnlySpan<FloorTriangle> floors)
    {
        var wallVertices = new List<D3>(walls.Vertices.Length);
        var corners = new List<D3>(floors.Length * 3);
        for (int p = 0; p < polygons.Count; p++)
        {
            (_, Vector3[] v, Vector3 normal) = polygons[p];
            D3[] e = exact[p];
            if (normal == Vector3.Zero)
            {
                continue; // no area
            }

            if (normal.Z < PhysicsConstants.FloorZ)
            {
                wallVertices.AddRange(e);
                continue;
            }

            FloorPlane? plane = FloorPlane.OfPolygon(v, normal);
            for (int i = 1; i + 1 < v.Length; i++)
            {
                if (FloorTriangle.TryCreate(v[0], v[i], v[i + 1], plane, out _))
                {
                    corners.Add(plane is null ? e[0] : OnPlane(e, e[0]));
                    corners.Add(plane is null ? e[i] : OnPlane(e, e[i]));
                    corners.Add(plane is null ? e[i + 1] : OnPlane(e, e[i + 1]));
                }
            }
        }

        if (wallVertices.Count != walls.Vertices.Length || corners.Count != floors.Length * 3)
        {
            throw new InvalidOperationException(
                $"the exact polygons ({wallVertices.Count} wall vertices, {corners.Count / 3} floor triangles) differ from the placed ones ({walls.Vertices.Length}, {floors.Length}).");
        }

        return wallVertices.Count == 0 && corners.Count == 0 ? None : new ExactPolygons([.. wallVertices], [.. corners]);
    }

    /// <summary><paramref name="p"/> moved along Z onto the plane of polygon <paramref name="v"/> (its Newell normal through its mean; the normal's Z is a floor's, far from 0).</summary>
    private static D3 OnPlane(D3[] v, D3 p)
    {
        (D3 n, D3 sum) = D3.Newell(v);
        (double cx, double cy, double cz) = (sum.X / v.Length, sum.Y / v.Length, sum.Z / v.Length);
        return new D3(p.X, p.Y, cz - (((n.X * (p.X - cx)) + (n.Y * (p.Y - cy))) / n.Z));
    }
}
