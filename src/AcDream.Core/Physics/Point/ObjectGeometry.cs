using System.Numerics;
using System.Runtime.CompilerServices;

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
    /// The ground a mover with its feet at <paramref name="feetZ"/> and step <paramref name="stepUp"/> comes to
    /// rest on at (x, y), from <paramref name="z"/> (the floor under it, <paramref name="found"/>): raised to the
    /// highest floor of <paramref name="objects"/> no more than the step above the feet, and again from there
    /// while that lifts it (a step from the terrain it climbed, a tread from a tread), until no floor within a
    /// step of where it stands is higher. What makes standing still on the answer give the answer again.
    /// <paramref name="objectIndex"/>: the object whose floor it rests on (−1: not raised).
    /// </summary>
    public static bool RaiseToRest(ReadOnlySpan<ObjectSurface> objects, float x, float y, float feetZ, float stepUp, bool found, ref float z, out int objectIndex)
    {
        objectIndex = -1;
        float ceiling = (found && z > feetZ ? z : feetZ) + stepUp;
        while (Raise(objects, x, y, ceiling, found, ref z, out int raised))
        {
            (found, objectIndex) = (true, raised);
            if (!(z > feetZ && z + stepUp > ceiling))
            {
                break;
            }

            ceiling = z + stepUp;
        }

        return objectIndex >= 0;
    }

    /// <summary>
    /// The first wall of <paramref name="objects"/> that the move <paramref name="p0"/> → <paramref name="p1"/>
    /// crosses at height <paramref name="h"/> (a point mover's feet plus its step: lower walls are steps),
    /// from either side, or floor that rises through that height ahead of it (<see cref="ObjectSurface.RisesThrough"/>),
    /// into <paramref name="hit"/>: the fraction along the move (only those before <c>hit.T</c> count), the horizontal
    /// unit normal facing the mover, the object, and whether it is a floor. A move that starts exactly on a wall's
    /// line may leave it; one that ends on it has crossed.
    /// </summary>
    public static void FirstCrossing(ReadOnlySpan<ObjectSurface> objects, Vector2 p0, Vector2 p1, float h, ref ObjectHit hit)
    {
        Vector2 lo = Vector2.Min(p0, p1), hi = Vector2.Max(p0, p1);
        for (int i = 0; i < objects.Length; i++)
        {
            if (Crosses(objects[i], p0, p1, lo, hi, h, ref hit.T, ref hit.Normal, ref hit.Rises))
            {
                hit.Wall = objects[i];
            }
        }
    }

    /// <summary>
    /// The objects standing outdoors in <paramref name="entry"/>'s landblock and in a neighbour whose objects
    /// reach over the seam that a point move meets, in one pass over those listed on the squares of each
    /// landblock's fine grid the move's box covers: when <paramref name="walls"/>, the first wall the move
    /// <paramref name="p0"/> → <paramref name="p1"/> (landblock-local to <paramref name="entry"/>) crosses at height
    /// <paramref name="h"/>, as <see cref="FirstCrossing(ReadOnlySpan{ObjectSurface}, Vector2, Vector2, float, ref ObjectHit)"/>;
    /// when <paramref name="floors"/>, the ground raised to the highest object floor under <paramref name="p1"/> no
    /// higher than <paramref name="h"/>, and whether an object may have a floor there above it
    /// (<see cref="ObjectHit.FloorAbove"/>). Into <paramref name="hit"/>.
    /// </summary>
    public static void AmongOutdoors(ref Neighbourhood lands, LandblockEntry entry, Vector2 p0, Vector2 p1, float h, bool walls, bool floors, ref ObjectHit hit)
    {
        AmongOutdoors(entry, p0, p1, h, walls, floors, ref hit);
        Vector2 lo = Vector2.Min(p0, p1), hi = Vector2.Max(p0, p1);
        if (lands.ReachInto(entry).Meets(lo, hi))
        {
            AcrossSeams(ref lands, entry, p0, p1, h, walls, floors, ref hit);
        }
    }

    /// <summary><see cref="AmongOutdoors(ref Neighbourhood, LandblockEntry, Vector2, Vector2, float, bool, bool, ref ObjectHit)"/> in the neighbours whose objects reach the move.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // out of the common path: only within a neighbour's reach
    private static void AcrossSeams(ref Neighbourhood lands, LandblockEntry entry, Vector2 p0, Vector2 p1, float h, bool walls, bool floors, ref ObjectHit hit)
    {
        SeamNeighbours across = Neighbourhood.Across(ref lands, entry, Vector2.Min(p0, p1), Vector2.Max(p0, p1));
        while (across.MoveNext())
        {
            AmongOutdoors(across.Current, p0 - across.Offset, p1 - across.Offset, h, walls, floors, ref hit);
        }
    }

    /// <summary>
    /// As <see cref="AmongOutdoors(ref Neighbourhood, LandblockEntry, Vector2, Vector2, float, bool, bool, ref ObjectHit)"/>,
    /// the objects of one landblock (the move in its frame). The objects' boxes (<see cref="LandblockEntry.ObjectBoxes"/>)
    /// reject them first, so only an object in reach is read.
    /// </summary>
    public static void AmongOutdoors(LandblockEntry entry, Vector2 p0, Vector2 p1, float h, bool walls, bool floors, ref ObjectHit hit)
    {
        if (entry.OutdoorObjects.Length == 0)
        {
            return;
        }

        Vector2 lo = Vector2.Min(p0, p1), hi = Vector2.Max(p0, p1);
        ObjectSurface[] objects = entry.OutdoorObjects;
        for (BoxGrid.Cursor near = entry.Objects.Near(lo, hi); near.MoveNext();)
        {
            int i = near.Current;
            ref readonly ObjectBox b = ref entry.ObjectBoxes[i];
            if (walls && b.ZMin < h && b.ZMax > h && Obstructs(objects[i], in b, p0, p1, h, ref hit))
            {
                hit.Wall = objects[i];
            }

            if (floors && p1.X >= b.FloorMin.X && p1.Y >= b.FloorMin.Y && p1.X <= b.FloorMax.X && p1.Y <= b.FloorMax.Y)
            {
                hit.FloorAbove |= b.ZMax > h;
                if (objects[i].TryFloorBelow(p1.X, p1.Y, h, out float z) && z > hit.GroundZ)
                {
                    (hit.GroundZ, hit.Floor) = (z, objects[i]);
                }
            }
        }
    }

    /// <summary>
    /// The ground a mover with its feet at <paramref name="feetZ"/> and step <paramref name="stepUp"/> comes to
    /// rest on outdoors at <paramref name="p"/> (landblock-local to <paramref name="entry"/>) over terrain at
    /// <paramref name="terrainZ"/>: raised to the highest floor of an outdoor object (of its landblock or of a
    /// neighbour's reaching over the seam) no more than the step above the feet, and on to rest as
    /// <see cref="RaiseToRest(ref Neighbourhood, LandblockEntry, Vector2, float, float, ref ObjectHit)"/>.
    /// </summary>
    public static ObjectHit GroundOutdoors(ref Neighbourhood lands, LandblockEntry entry, Vector2 p, float feetZ, float stepUp, float terrainZ)
    {
        var hit = ObjectHit.Over(terrainZ);
        AmongOutdoors(ref lands, entry, p, p, feetZ + stepUp, walls: false, floors: true, ref hit);
        RaiseToRest(ref lands, entry, p, feetZ, stepUp, ref hit);
        return hit;
    }

    /// <summary>
    /// Outdoors, after a first pass for floors at the feet plus the step: the ground of <paramref name="hit"/> (at
    /// <paramref name="p"/>) raised on from where it stands, when that is above the feet (a mover that climbed
    /// the terrain or a step reaches a floor higher than the feet plus the step) and an object may have a floor
    /// above (<see cref="ObjectHit.FloorAbove"/>), until no floor within a step of it is higher: what makes standing
    /// still on the answer give the answer again.
    /// </summary>
    public static void RaiseToRest(ref Neighbourhood lands, LandblockEntry entry, Vector2 p, float feetZ, float stepUp, ref ObjectHit hit)
    {
        float ceiling = feetZ + stepUp;
        while (hit.FloorAbove && hit.GroundZ > feetZ && hit.GroundZ + stepUp > ceiling)
        {
            ceiling = hit.GroundZ + stepUp;
            float ground = hit.GroundZ;
            hit.FloorAbove = false;
            AmongOutdoors(ref lands, entry, p, p, ceiling, walls: false, floors: true, ref hit);
            if (hit.GroundZ == ground)
            {
                return;
            }
        }
    }

    /// <summary>Whether the move (box <paramref name="lo"/>–<paramref name="hi"/>) crosses a wall of <paramref name="o"/> at height <paramref name="h"/> before <paramref name="t"/>; the object's bounds reject it first.</summary>
    private static bool Crosses(ObjectSurface o, Vector2 p0, Vector2 p1, Vector2 lo, Vector2 hi, float h, ref float t, ref Vector3 normal, ref bool rises)
    {
        if (!(o.BoundsMin.X <= hi.X && o.BoundsMax.X >= lo.X && o.BoundsMin.Y <= hi.Y && o.BoundsMax.Y >= lo.Y && o.BoundsMin.Z < h && o.BoundsMax.Z > h))
        {
            return false;
        }

        bool met = FirstCrossing(o.Walls, p0, p1, lo, hi, h, ref t, ref normal);
        rises &= !met;
        if (o.RisesThrough(p0, p1, lo, hi, h, ref t, ref normal))
        {
            (met, rises) = (true, true);
        }

        return met;
    }

    /// <summary>
    /// What of outdoor object <paramref name="o"/> (its box <paramref name="b"/>) the point move meets first at its step
    /// line <paramref name="h"/>, into <paramref name="hit"/>: a wall it crosses, or a floor rising through the line
    /// (<see cref="ObjectSurface.RisesThrough"/>). True when it is met before what <paramref name="hit"/> held.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool Obstructs(ObjectSurface o, in ObjectBox b, Vector2 p0, Vector2 p1, float h, ref ObjectHit hit)
    {
        Vector2 lo = Vector2.Min(p0, p1), hi = Vector2.Max(p0, p1);
        bool met = b.WallMin.X <= hi.X && b.WallMax.X >= lo.X && b.WallMin.Y <= hi.Y && b.WallMax.Y >= lo.Y
            && FirstCrossing(o.Walls, p0, p1, lo, hi, h, ref hit.T, ref hit.Normal);
        hit.Rises &= !met;
        if (b.FloorMin.X <= hi.X && b.FloorMax.X >= lo.X && b.FloorMin.Y <= hi.Y && b.FloorMax.Y >= lo.Y
            && o.RisesThrough(p0, p1, lo, hi, h, ref hit.T, ref hit.Normal))
        {
            (met, hit.Rises) = (true, true);
        }

        return met;
    }

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

/// <summary>
/// What a point move meets among objects: the first object wall its segment crosses (<see cref="T"/>, the
/// fraction of the move, above 1 for none; <see cref="Normal"/>, facing the mover; <see cref="Wall"/>), and
/// the ground under its end raised to the highest object floor within reach (<see cref="GroundZ"/>,
/// <see cref="Floor"/>: null when no object's floor raised it).
/// </summary>
internal ref struct ObjectHit
{
    public float T;
    public Vector3 Normal;
    public ObjectSurface? Wall;

    /// <summary>Whether what <see cref="Wall"/> met first is one of its floors rising through the step line (a rise too high), not a wall.</summary>
    public bool Rises;
    public float GroundZ;
    public ObjectSurface? Floor;

    /// <summary>Whether an object whose floors' bounds hold the end point reaches above the height a floors pass looked up to: a higher floor may be there.</summary>
    public bool FloorAbove;

    /// <summary>Nothing met yet, over ground at <paramref name="groundZ"/>.</summary>
    public static ObjectHit Over(float groundZ) => new() { T = 2f, GroundZ = groundZ };
}
