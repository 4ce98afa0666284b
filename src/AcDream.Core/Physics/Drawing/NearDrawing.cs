using System.Numerics;
using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Movers;
using AcDream.Core.Physics.Point;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Drawing;

/// <summary>
/// Draws the surfaces of a landblock (and the committed movers) whose bounds, seen from above, meet a box of its frame:
/// terrain triangles, cells' floors, walls and portals, objects' floors, walls and cylinders. Every point is one of the
/// surface's own (a polygon's vertex, a floor triangle's corner at its Z, a portal's vertex, a point on a cylinder's
/// radius), turned to the world frame by adding the landblock's origin.
/// </summary>
internal static class NearDrawing
{
    /// <summary>How many sides a cylinder is drawn with.</summary>
    public const int CylinderSides = 12;

    /// <summary>The landblock <paramref name="entry"/>'s surfaces that meet <paramref name="box"/> (its frame).</summary>
    public static void Landblock<TSink>(in WorldFrame frame, LandblockEntry entry, Box box, ref TSink sink)
        where TSink : IDebugSink
    {
        var at = new At(frame, entry.X, entry.Y);
        Terrain(in at, entry.Terrain, box, ref sink);
        CellSurface[] cells = entry.Cells;
        for (int i = 0; i < cells.Length; i++)
        {
            CellSurface cell = cells[i];
            WallBounds bounds = entry.CellWallBounds[i];
            bool walls = box.Meets(bounds.Min, bounds.Max);
            bool floors = cell.HasFloor && box.Meets(cell.FloorMin, cell.FloorMax);
            if (!walls && !floors)
            {
                continue;
            }

            Floors(in at, cell.Floors, box, DrawKind.CellFloor, cell.CellId, ref sink);
            Walls(in at, cell.Walls, box, DrawKind.CellWall, cell.CellId, ref sink);
            foreach (PortalShape portal in cell.PortalShapes)
            {
                if (box.Meets(portal.BoundsMin, portal.BoundsMax))
                {
                    Portal(in at, portal, cell.CellId, ref sink);
                }
            }

            foreach (ObjectSurface o in cell.Objects)
            {
                Object(in at, o, box, ref sink);
            }
        }

        foreach (ObjectSurface o in entry.OutdoorObjects)
        {
            Object(in at, o, box, ref sink);
        }
    }

    /// <summary>The committed movers (<paramref name="movers"/>) whose walls meet <paramref name="box"/> (the frame of landblock x, y).</summary>
    public static void Movers<TSink>(in WorldFrame frame, MoverFrame movers, int x, int y, Box box, ref TSink sink)
        where TSink : IDebugSink
    {
        for (int i = 0; i < movers.Count; i++)
        {
            if (movers.TryOffset(i, x, y, out Vector2 offset, out _))
            {
                var at = new At(frame, movers.LandblockX[i], movers.LandblockY[i]);
                Walls(in at, movers.Walls[i], box.Moved(-offset), DrawKind.Mover, movers.Ids[i], ref sink);
            }
        }
    }

    /// <summary>The two triangles of each outdoor cell meeting the box, split as the terrain's cell is.</summary>
    private static void Terrain<TSink>(in At at, TerrainSurface terrain, Box box, ref TSink sink)
        where TSink : IDebugSink
    {
        const float size = PhysicsConstants.CellSize;
        if (box.Hi.X < 0f || box.Hi.Y < 0f || box.Lo.X > PhysicsConstants.LandblockSize || box.Lo.Y > PhysicsConstants.LandblockSize)
        {
            return;
        }

        int x0 = CellIds.OutdoorColumn(Math.Max(box.Lo.X, 0f)), x1 = CellIds.OutdoorColumn(Math.Min(box.Hi.X, PhysicsConstants.LandblockSize));
        int y0 = CellIds.OutdoorColumn(Math.Max(box.Lo.Y, 0f)), y1 = CellIds.OutdoorColumn(Math.Min(box.Hi.Y, PhysicsConstants.LandblockSize));
        for (int cx = x0; cx <= x1; cx++)
        {
            for (int cy = y0; cy <= y1; cy++)
            {
                terrain.Corners(cx, cy, out double hsw, out double hnw, out double hse, out double hne);
                Vector3 sw = at.World(new Vector2(cx * size, cy * size), (float)hsw);
                Vector3 nw = at.World(new Vector2(cx * size, (cy + 1) * size), (float)hnw);
                Vector3 se = at.World(new Vector2((cx + 1) * size, cy * size), (float)hse);
                Vector3 ne = at.World(new Vector2((cx + 1) * size, (cy + 1) * size), (float)hne);
                uint id = CellIds.Prefix(at.X, at.Y) | (uint)((cx * PhysicsConstants.CellsPerSide) + cy + 1);
                if (terrain.IsSplitSwToNe(cx, cy))
                {
                    sink.Triangle(sw, se, ne, DrawKind.Terrain, id);
                    sink.Triangle(sw, ne, nw, DrawKind.Terrain, id);
                }
                else
                {
                    sink.Triangle(sw, se, nw, DrawKind.Terrain, id);
                    sink.Triangle(se, ne, nw, DrawKind.Terrain, id);
                }
            }
        }
    }

    private static void Object<TSink>(in At at, ObjectSurface o, Box box, ref TSink sink)
        where TSink : IDebugSink
    {
        Vector2 min = new(o.BoundsMin.X, o.BoundsMin.Y), max = new(o.BoundsMax.X, o.BoundsMax.Y);
        if (o.FloorMin.X <= o.FloorMax.X)
        {
            (min, max) = (Vector2.Min(min, o.FloorMin), Vector2.Max(max, o.FloorMax));
        }

        if (box.Meets(min, max))
        {
            Floors(in at, o.Floors, box, DrawKind.ObjectFloor, o.ObjectId, ref sink);
            Walls(in at, o.Walls, box, DrawKind.ObjectWall, o.ObjectId, ref sink);
        }
    }

    private static void Floors<TSink>(in At at, ReadOnlySpan<FloorTriangle> floors, Box box, DrawKind kind, uint id, ref TSink sink)
        where TSink : IDebugSink
    {
        foreach (ref readonly FloorTriangle t in floors)
        {
            if (box.Meets(t.Min, t.Max))
            {
                Triangle(in at, in t, kind, id, ref sink);
            }
        }
    }

    /// <summary>A floor triangle as the engine samples it: each corner at the triangle's Z there.</summary>
    public static void Triangle<TSink>(in At at, in FloorTriangle t, DrawKind kind, uint id, ref TSink sink)
        where TSink : IDebugSink =>
        sink.Triangle(at.World(t.A, t.ZAt(t.A)), at.World(t.B, t.ZAt(t.B)), at.World(t.C, t.ZAt(t.C)), kind, id);

    /// <summary>
    /// Each wall polygon's edges; a cylinder (<see cref="WallPolygon.Radius"/> &gt; 0) as <see cref="CylinderSides"/> uprights
    /// and the chords of its bottom and top rings (<see cref="DrawKind.Cylinder"/> unless <paramref name="kind"/> is a mover's).
    /// </summary>
    private static void Walls<TSink>(in At at, CellWalls walls, Box box, DrawKind kind, uint id, ref TSink sink)
        where TSink : IDebugSink
    {
        if (walls.Polygons.Length == 0 || !box.Meets(walls.Min, walls.Max))
        {
            return;
        }

        foreach (WallPolygon w in walls.Polygons)
        {
            if (!box.Meets(w.Min, w.Max))
            {
                continue;
            }

            if (w.Radius > 0f)
            {
                Cylinder(in at, w, kind == DrawKind.Mover ? kind : DrawKind.Cylinder, id, ref sink);
                continue;
            }

            ReadOnlySpan<Vector3> v = walls.Vertices.AsSpan(w.First, w.Count);
            for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
            {
                sink.Line(at.World(v[j]), at.World(v[i]), kind, id);
            }
        }
    }

    private static void Cylinder<TSink>(in At at, WallPolygon w, DrawKind kind, uint id, ref TSink sink)
        where TSink : IDebugSink
    {
        Vector2 previous = Around(w, CylinderSides - 1);
        for (int k = 0; k < CylinderSides; k++)
        {
            Vector2 p = Around(w, k);
            sink.Line(at.World(p, w.ZMin), at.World(p, w.ZMax), kind, id);
            sink.Line(at.World(previous, w.ZMin), at.World(p, w.ZMin), kind, id);
            sink.Line(at.World(previous, w.ZMax), at.World(p, w.ZMax), kind, id);
            previous = p;
        }

        static Vector2 Around(WallPolygon w, int k)
        {
            double angle = 2.0 * Math.PI * k / CylinderSides;
            return new Vector2((float)(w.A.X + (w.Radius * Math.Cos(angle))), (float)(w.A.Y + (w.Radius * Math.Sin(angle))));
        }
    }

    /// <summary>A portal's polygon: a horizontal one's outline at its plane's Z; a vertical one's profile along its plane.</summary>
    private static void Portal<TSink>(in At at, PortalShape portal, uint id, ref TSink sink)
        where TSink : IDebugSink
    {
        if (portal.Kind == PortalKind.Horizontal)
        {
            ReadOnlySpan<Vector2> outline = portal.Outline;
            for (int i = 0, j = outline.Length - 1; i < outline.Length; j = i++)
            {
                sink.Line(at.World(outline[j], portal.PlaneZ(outline[j].X, outline[j].Y)), at.World(outline[i], portal.PlaneZ(outline[i].X, outline[i].Y)), DrawKind.Portal, id);
            }
        }
        else if (portal.Kind == PortalKind.Vertical)
        {
            ReadOnlySpan<Vector2> profile = portal.ProfilePoints;
            for (int i = 0, j = profile.Length - 1; i < profile.Length; j = i++)
            {
                sink.Line(at.World(OnPlane(portal, profile[j]), profile[j].Y), at.World(OnPlane(portal, profile[i]), profile[i].Y), DrawKind.Portal, id);
            }
        }
    }

    /// <summary>
    /// A vertical portal's vertex from its profile point (along the tangent, Z): on the portal's plane, which a portal
    /// leaning from the vertical crosses away from its origin's upright line (the horizontal normal's share of the height).
    /// </summary>
    private static Vector2 OnPlane(PortalShape portal, Vector2 profile)
    {
        var across = new Vector2(portal.OutNormal.X, portal.OutNormal.Y);
        float length = across.Length();
        float off = -portal.OutNormal.Z * (profile.Y - portal.Origin.Z) / length;
        return new Vector2(portal.Origin.X, portal.Origin.Y) + (portal.Tangent * profile.X) + (across * (off / length));
    }

    /// <summary>A box seen from above, in a landblock's frame (metres): what is drawn meets it.</summary>
    public readonly record struct Box(Vector2 Lo, Vector2 Hi)
    {
        /// <summary>Whether bounds <paramref name="min"/>..<paramref name="max"/> meet the box (edges touching count).</summary>
        public bool Meets(Vector2 min, Vector2 max) => min.X <= Hi.X && max.X >= Lo.X && min.Y <= Hi.Y && max.Y >= Lo.Y;

        /// <summary>The same box moved by <paramref name="by"/>.</summary>
        public Box Moved(Vector2 by) => new(Lo + by, Hi + by);
    }

    /// <summary>A landblock's place in the world frame: landblock-local points to world.</summary>
    internal readonly struct At(WorldFrame frame, int x, int y)
    {
        public int X { get; } = x;

        public int Y { get; } = y;

        public Vector3 World(Vector2 local, float z) => frame.ToWorld(X, Y, local, z);

        public Vector3 World(Vector3 local) => frame.ToWorld(X, Y, new Vector2(local.X, local.Y), local.Z);
    }
}
