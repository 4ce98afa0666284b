using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics;

// CellSurface, how a cell is built from the dat: its physics polygons placed in landblock-local space
// (CellTransform), its floors fan-triangulated and bounded, its portals prepared, an orientation normalised.
public sealed partial class CellSurface
{
    /// <summary>The physics polygons placed in landblock-local space, in id order, each with its winding normal (zero when it has no area).</summary>
    private static List<(ushort Id, Vector3[] Vertices, Vector3 Normal)> PlacePhysicsPolygons(string cell, CellStruct cellStruct, CellTransform transform)
    {
        Dictionary<ushort, Polygon> polygons = cellStruct.PhysicsPolygons
            ?? throw new ArgumentNullException(nameof(cellStruct), $"{cell}: cellStruct.PhysicsPolygons is null.");
        var keys = new List<ushort>(polygons.Keys);
        keys.Sort();
        var placed = new List<(ushort, Vector3[], Vector3)>(keys.Count);
        foreach (ushort key in keys)
        {
            Vector3[] v = transform.Polygon(polygons[key], $"physics polygon {key}");
            placed.Add((key, v, Geometry.NewellNormal(v, v[0])));
        }

        return placed;
    }

    /// <summary>XY bounds of <paramref name="floors"/> (each triangle's, grown by the edge tolerance), landblock-local metres; with no floors, an empty box that contains nothing.</summary>
    internal static (Vector2 Min, Vector2 Max) FloorBounds(FloorTriangle[] floors)
    {
        Vector2 min = new(float.MaxValue), max = new(float.MinValue);
        foreach (FloorTriangle t in floors)
        {
            min = Vector2.Min(min, t.Min);
            max = Vector2.Max(max, t.Max);
        }

        return (min, max);
    }

    /// <summary>The walkable polygons (winding normal Z ≥ <see cref="PhysicsConstants.FloorZ"/>), fan-triangulated.</summary>
    internal static FloorTriangle[] BuildFloors(List<(ushort Id, Vector3[] Vertices, Vector3 Normal)> physics)
    {
        var triangles = new List<FloorTriangle>();
        foreach ((_, Vector3[] v, Vector3 normal) in physics)
        {
            if (normal.Z < PhysicsConstants.FloorZ)
            {
                continue; // a wall, a ceiling, too steep, or no area
            }

            FloorPlane? plane = FloorPlane.OfPolygon(v, normal);
            for (int i = 1; i + 1 < v.Length; i++)
            {
                if (FloorTriangle.TryCreate(v[0], v[i], v[i + 1], plane, out FloorTriangle triangle))
                {
                    triangles.Add(triangle);
                }
            }
        }

        return [.. triangles];
    }

    private static (CellPortalInfo[] Infos, PortalShape[] Shapes) BuildPortals(
        string cell, uint cellId, EnvCell envCell, CellStruct cellStruct, CellTransform transform)
    {
        List<CellPortal> portals = envCell.CellPortals
            ?? throw new ArgumentNullException(nameof(envCell), $"{cell}: envCell.CellPortals is null.");
        Dictionary<ushort, Polygon> polygons = cellStruct.Polygons
            ?? throw new ArgumentNullException(nameof(cellStruct), $"{cell}: cellStruct.Polygons is null.");
        var infos = new CellPortalInfo[portals.Count];
        var shapes = new PortalShape[portals.Count];
        for (int i = 0; i < portals.Count; i++)
        {
            CellPortal portal = portals[i] ?? throw new ArgumentNullException(nameof(envCell), $"{cell}: CellPortals[{i}] is null.");
            if (!polygons.TryGetValue(portal.PolygonId, out Polygon? polygon))
            {
                throw new ArgumentException(
                    $"{cell}: portal {i} (to 0x{portal.OtherCellId:X4}) names polygon {portal.PolygonId}, which cellStruct.Polygons lacks.",
                    nameof(cellStruct));
            }

            Vector3[] v = transform.Polygon(polygon, $"portal {i} polygon {portal.PolygonId}");
            bool cellOnPositiveSide = (portal.Flags & PortalFlags.PortalSide) != 0;
            PortalShape shape = PortalShape.Create(v, cellOnPositiveSide);
            shapes[i] = shape;
            infos[i] = new CellPortalInfo(CellIds.Prefix(cellId) | portal.OtherCellId, shape.Origin, shape.OutNormal);
        }

        return (infos, shapes);
    }

    /// <summary>
    /// <paramref name="q"/> normalised to a unit rotation; false when it is not finite or
    /// shorter than <see cref="PhysicsConstants.MinOrientationLength"/>. Normalised in double: a float
    /// LengthSquared overflows for a quaternion longer than ~1.8e19 (and Quaternion.Normalize then
    /// returns zero, which rotates nothing).
    /// </summary>
    internal static bool TryUnitOrientation(Quaternion q, out Quaternion unit)
    {
        double length = Math.Sqrt(((double)q.X * q.X) + ((double)q.Y * q.Y) + ((double)q.Z * q.Z) + ((double)q.W * q.W));
        if (!float.IsFinite(q.X) || !float.IsFinite(q.Y) || !float.IsFinite(q.Z) || !float.IsFinite(q.W)
            || !(length >= PhysicsConstants.MinOrientationLength))
        {
            unit = default;
            return false;
        }

        unit = new Quaternion((float)(q.X / length), (float)(q.Y / length), (float)(q.Z / length), (float)(q.W / length));
        return true;
    }

    /// <summary>Moves a CellStruct's vertices to landblock-local space, validating them once each.</summary>
    private sealed class CellTransform(string cell, CellStruct cellStruct, Vector3 origin, Quaternion orientation)
    {
        private readonly Dictionary<ushort, SWVertex> _vertices = cellStruct.VertexArray?.Vertices
            ?? throw new ArgumentNullException(nameof(cellStruct), $"{cell}: cellStruct.VertexArray.Vertices is null.");

        private readonly Dictionary<short, Vector3> _moved = [];

        public Vector3[] Polygon(Polygon polygon, string what)
        {
            List<short> ids = polygon?.VertexIds
                ?? throw new ArgumentNullException(nameof(cellStruct), $"{cell}: {what} or its VertexIds is null.");
            if (ids.Count < 3)
            {
                throw new ArgumentException($"{cell}: {what} has {ids.Count} vertices; a polygon needs at least 3.", nameof(cellStruct));
            }

            var result = new Vector3[ids.Count];
            for (int i = 0; i < ids.Count; i++)
            {
                result[i] = Vertex(ids[i], what);
            }

            return result;
        }

        private Vector3 Vertex(short id, string what)
        {
            if (_moved.TryGetValue(id, out Vector3 moved))
            {
                return moved;
            }

            if (id < 0 || !_vertices.TryGetValue((ushort)id, out SWVertex? vertex) || vertex is null)
            {
                throw new ArgumentException($"{cell}: {what} names vertex {id}, which the vertex array lacks.", nameof(cellStruct));
            }

            Vector3 local = vertex.Origin;
            if (!Geometry.IsFinite(local))
            {
                throw new ArgumentException($"{cell}: vertex {id} ({what}) is {local}; vertices must be finite.", nameof(cellStruct));
            }

            moved = origin + Vector3.Transform(local, orientation);
            if (!(MathF.Abs(moved.X) <= PhysicsConstants.MaxCellCoordinate && MathF.Abs(moved.Y) <= PhysicsConstants.MaxCellCoordinate
                && MathF.Abs(moved.Z) <= PhysicsConstants.MaxCellCoordinate))
            {
                throw new ArgumentException(
                    $"{cell}: vertex {id} ({what}) is placed at {moved}, farther than {PhysicsConstants.MaxCellCoordinate} m from the landblock.",
                    nameof(cellStruct));
            }

            _moved[id] = moved;
            return moved;
        }
    }
}
