using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// The two questions a point mover asks of the objects near it, allocation-free: which object floor it
/// stands on, and whether its move crosses an object's wall. Landblock-local metres throughout.
/// </summary>
internal static class ObjectGeometry
{
    /// <summary>
    /// Raises <paramref name="z"/> to the highest floor of <paramref name="objects"/> under (x, y) that is
    /// no higher than <paramref name="ceilingZ"/>, when that is above <paramref name="z"/> (or when
    /// <paramref name="found"/> is false: there is no floor yet). Returns whether it raised it; then
    /// <paramref name="objectIndex"/> is the object's index.
    /// </summary>
    public static bool Raise(ReadOnlySpan<ObjectSurface> objects, float x, float y, float ceilingZ, bool found, ref float z, out int objectIndex)
    {
        objectIndex = -1;
        for (int i = 0; i < objects.Length; i++)
        {
            if (objects[i].TryFloorBelow(x, y, ceilingZ, out float floor) && (!found || floor > z))
            {
                (z, found, objectIndex) = (floor, true, i);
            }
        }

        return objectIndex >= 0;
    }

    /// <summary>
    /// <see cref="Raise(ReadOnlySpan{ObjectSurface}, float, float, float, bool, ref float, out int)"/> over
    /// the outdoor objects a landblock lists over the square of its fine grid (<see cref="LandblockEntry.ObjectsAt"/>) under (x, y).
    /// </summary>
    public static bool RaiseOutdoors(LandblockEntry entry, float x, float y, float ceilingZ, bool found, ref float z, out int objectIndex)
    {
        objectIndex = -1;
        if (entry.OutdoorObjects.Length == 0)
        {
            return false; // no grid
        }

        ObjectSurface[] objects = entry.OutdoorObjects;
        foreach (int i in entry.ObjectsAt(LandblockEntry.ObjectGridColumn(x), LandblockEntry.ObjectGridColumn(y)))
        {
            if (objects[i].TryFloorBelow(x, y, ceilingZ, out float floor) && (!found || floor > z))
            {
                (z, found, objectIndex) = (floor, true, i);
            }
        }

        return objectIndex >= 0;
    }

    /// <summary>
    /// Whether any outdoor object of <paramref name="entry"/> is listed over the fine-grid squares of the
    /// box of <paramref name="p0"/> → <paramref name="p1"/> grown by <see cref="NearMargin"/> (so rounding
    /// the move into its landblock's frame never leaves a square out). False means every object question
    /// about the move has no answer: no floor under its ends, no wall it crosses.
    /// </summary>
    public static bool AnyOutdoors(LandblockEntry entry, Vector2 p0, Vector2 p1)
    {
        Vector2 lo = Vector2.Min(p0, p1) - new Vector2(NearMargin), hi = Vector2.Max(p0, p1) + new Vector2(NearMargin);
        int x0 = LandblockEntry.ObjectGridColumn(lo.X), x1 = LandblockEntry.ObjectGridColumn(hi.X);
        int y0 = LandblockEntry.ObjectGridColumn(lo.Y), y1 = LandblockEntry.ObjectGridColumn(hi.Y);
        int[] starts = entry.ObjectGridStarts;
        for (int cx = x0; cx <= x1; cx++)
        {
            int k = (cx * LandblockEntry.ObjectGridSide) + y0;
            if (starts[k] != starts[k + (y1 - y0) + 1])
            {
                return true; // squares k .. k + (y1 − y0) of this column list at least one object
            }
        }

        return false;
    }

    /// <summary>Margin of <see cref="AnyOutdoors"/>, metres.</summary>
    public const float NearMargin = 0.01f;

    /// <summary>
    /// The first wall of <paramref name="objects"/> that the move <paramref name="p0"/> → <paramref name="p1"/>
    /// crosses at height <paramref name="h"/> (a point mover's feet plus its step: lower walls are steps),
    /// from either side: fraction <paramref name="t"/> along the move (only crossings before the
    /// <paramref name="t"/> given count), the wall's horizontal unit normal facing the mover, and the object.
    /// A move that starts exactly on a wall's line may leave it; one that ends on it has crossed.
    /// </summary>
    public static void FirstCrossing(ReadOnlySpan<ObjectSurface> objects, Vector2 p0, Vector2 p1, float h, ref float t, ref Vector3 normal, ref int objectIndex)
    {
        Vector2 lo = Vector2.Min(p0, p1), hi = Vector2.Max(p0, p1);
        for (int i = 0; i < objects.Length; i++)
        {
            if (Crosses(objects[i], p0, p1, lo, hi, h, ref t, ref normal))
            {
                objectIndex = i;
            }
        }
    }

    /// <summary>
    /// The outdoor objects of <paramref name="entry"/> a move meets, in one pass over those listed on the
    /// squares of its fine grid the move's box covers (<see cref="LandblockEntry.ObjectsAt"/>; an object over
    /// several of them is tested again, with the same answer): the first wall the move
    /// <paramref name="p0"/> → <paramref name="p1"/> crosses at height <paramref name="h"/>, as
    /// <see cref="FirstCrossing(ReadOnlySpan{ObjectSurface}, Vector2, Vector2, float, ref float, ref Vector3, ref int)"/>
    /// (<paramref name="wall"/>: the object); and, when <paramref name="floors"/>, <paramref name="groundZ"/>
    /// raised to the highest object floor under <paramref name="p1"/> no higher than <paramref name="h"/>
    /// (<paramref name="floor"/>: the object; the end point's square is among those of the box). The
    /// objects' boxes (<see cref="LandblockEntry.ObjectBoxes"/>) reject them first, so only an object in
    /// reach is read.
    /// </summary>
    public static void AmongOutdoors(
        LandblockEntry entry, Vector2 p0, Vector2 p1, float h, ref float t, ref Vector3 normal, ref int wall, bool floors, ref float groundZ, ref int floor)
    {
        if (entry.OutdoorObjects.Length == 0)
        {
            return; // no grid
        }

        Vector2 lo = Vector2.Min(p0, p1), hi = Vector2.Max(p0, p1);
        int x0 = LandblockEntry.ObjectGridColumn(lo.X), x1 = LandblockEntry.ObjectGridColumn(hi.X);
        int y0 = LandblockEntry.ObjectGridColumn(lo.Y), y1 = LandblockEntry.ObjectGridColumn(hi.Y);
        ObjectSurface[] objects = entry.OutdoorObjects;
        ObjectBox[] boxes = entry.ObjectBoxes;
        for (int cx = x0; cx <= x1; cx++)
        {
            for (int cy = y0; cy <= y1; cy++)
            {
                foreach (int i in entry.ObjectsAt(cx, cy))
                {
                    ref readonly ObjectBox b = ref boxes[i];
                    if (b.WallMin.X <= hi.X && b.WallMax.X >= lo.X && b.WallMin.Y <= hi.Y && b.WallMax.Y >= lo.Y && b.ZMin < h && b.ZMax > h
                        && FirstCrossing(objects[i].Walls, p0, p1, lo, hi, h, ref t, ref normal))
                    {
                        wall = i;
                    }

                    if (floors && p1.X >= b.FloorMin.X && p1.Y >= b.FloorMin.Y && p1.X <= b.FloorMax.X && p1.Y <= b.FloorMax.Y
                        && objects[i].TryFloorBelow(p1.X, p1.Y, h, out float z) && z > groundZ)
                    {
                        (groundZ, floor) = (z, i);
                    }
                }
            }
        }
    }

    /// <summary>Whether the move (box <paramref name="lo"/>–<paramref name="hi"/>) crosses a wall of <paramref name="o"/> at height <paramref name="h"/> before <paramref name="t"/>; the object's bounds reject it first.</summary>
    private static bool Crosses(ObjectSurface o, Vector2 p0, Vector2 p1, Vector2 lo, Vector2 hi, float h, ref float t, ref Vector3 normal) =>
        o.BoundsMin.X <= hi.X && o.BoundsMax.X >= lo.X && o.BoundsMin.Y <= hi.Y && o.BoundsMax.Y >= lo.Y
        && o.BoundsMin.Z < h && o.BoundsMax.Z > h
        && FirstCrossing(o.Walls, p0, p1, lo, hi, h, ref t, ref normal);

    private static bool FirstCrossing(CellWalls walls, Vector2 p0, Vector2 p1, Vector2 lo, Vector2 hi, float h, ref float t, ref Vector3 normal)
    {
        bool hit = false;
        ReadOnlySpan<Vector3> vertices = walls.Vertices;
        foreach (ref readonly WallPolygon w in walls.Polygons.AsSpan())
        {
            if (!(w.ZMin < h && w.ZMax > h) || w.Min.X > hi.X || w.Max.X < lo.X || w.Min.Y > hi.Y || w.Max.Y < lo.Y)
            {
                continue;
            }

            if (w.Radius > 0f)
            {
                hit |= CrossCircle(p0, p1, w.A, w.Radius, ref t, ref normal);
            }
            else if (w.IsUpright)
            {
                hit |= CrossSegment(p0, p1, w.A, w.B, ref t, ref normal);
            }
            else if (Cut(vertices.Slice(w.First, w.Count), h, out Vector2 a, out Vector2 b))
            {
                hit |= CrossSegment(p0, p1, a, b, ref t, ref normal);
            }
        }

        return hit;
    }

    /// <summary>Where a convex polygon meets the plane z = <paramref name="h"/>: the chord between its extreme crossing points.</summary>
    private static bool Cut(ReadOnlySpan<Vector3> v, float h, out Vector2 a, out Vector2 b)
    {
        (a, b) = (default, default);
        int n = 0;
        for (int i = 0; i < v.Length; i++)
        {
            Vector3 p = v[i], q = v[(i + 1) % v.Length];
            if ((p.Z < h) == (q.Z < h))
            {
                continue;
            }

            float s = (h - p.Z) / (q.Z - p.Z);
            var point = new Vector2(p.X + ((q.X - p.X) * s), p.Y + ((q.Y - p.Y) * s));
            if (n == 0)
            {
                a = point;
            }
            else if (n == 1 || Vector2.DistanceSquared(a, point) > Vector2.DistanceSquared(a, b))
            {
                b = point;
            }

            n++;
        }

        return n >= 2 && a != b;
    }

    /// <summary>The move crosses segment a–b (from either side, onto or through its line, within its ends) before <paramref name="t"/>.</summary>
    private static bool CrossSegment(Vector2 p0, Vector2 p1, Vector2 a, Vector2 b, ref float t, ref Vector3 normal)
    {
        Vector2 ab = b - a;
        float s0 = Cross(ab, p0 - a), s1 = Cross(ab, p1 - a);
        if (s0 == 0f || (s0 > 0f && s1 > 0f) || (s0 < 0f && s1 < 0f))
        {
            return false; // starts on the line (may leave it) or stays on one side
        }

        float at = s0 / (s0 - s1);
        Vector2 point = p0 + ((p1 - p0) * at);
        float u = Vector2.Dot(point - a, ab) / ab.LengthSquared();
        if (!(u >= 0f && u <= 1f) || !(at < t))
        {
            return false;
        }

        Vector2 n = Vector2.Normalize(s0 > 0f ? new Vector2(-ab.Y, ab.X) : new Vector2(ab.Y, -ab.X));
        (t, normal) = (at, new Vector3(n, 0f));
        return true;
    }

    /// <summary>The move enters the circle (centre <paramref name="c"/>, radius <paramref name="r"/>) before <paramref name="t"/>; a move starting inside may leave.</summary>
    private static bool CrossCircle(Vector2 p0, Vector2 p1, Vector2 c, float r, ref float t, ref Vector3 normal)
    {
        Vector2 d = p1 - p0, f = p0 - c;
        float a = d.LengthSquared(), b = Vector2.Dot(f, d), k = f.LengthSquared() - (r * r);
        if (k <= 0f || b >= 0f || a == 0f)
        {
            return false; // starts inside (or on) the circle, or moves away from it
        }

        float disc = (b * b) - (a * k);
        if (disc < 0f)
        {
            return false;
        }

        float at = (-b - MathF.Sqrt(disc)) / a;
        if (!(at <= 1f) || !(at < t))
        {
            return false;
        }

        at = MathF.Max(at, 0f);
        Vector2 n = f + (d * at);
        float length = n.Length();
        (t, normal) = (at, length > 0f ? new Vector3(n / length, 0f) : new Vector3(-d / MathF.Sqrt(a), 0f));
        return true;
    }

    private static float Cross(Vector2 u, Vector2 v) => (u.X * v.Y) - (u.Y * v.X);
}
