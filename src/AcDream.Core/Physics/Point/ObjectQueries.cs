using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Point;

/// <summary>
/// The two questions a point mover asks of the objects near it, allocation-free: which object floor it
/// stands on, and whether its step line (<see cref="StepLine"/>) crosses an object's wall. Landblock-local
/// metres throughout.
/// </summary>
internal static class ObjectQueries
{
    /// <summary>
    /// The first wall of <paramref name="objects"/> that <paramref name="line"/> crosses, from either side, or floor
    /// that rises through its height ahead of it (<see cref="ObjectSurface.RisesThrough"/>), into <paramref name="hit"/>:
    /// the fraction along the move (only those before <c>hit.T</c> count), the horizontal unit normal facing the mover,
    /// the object, and whether it is a floor. A move that starts exactly on a wall's line may leave it; one that ends
    /// on it has crossed.
    /// </summary>
    public static void FirstCrossing(ReadOnlySpan<ObjectSurface> objects, in StepLine line, ref ObjectHit hit)
    {
        for (int i = 0; i < objects.Length; i++)
        {
            if (Crosses(objects[i], in line, ref hit))
            {
                hit.Wall = objects[i];
            }
        }
    }

    /// <summary>
    /// The objects standing outdoors in <paramref name="entry"/>'s landblock and in a neighbour whose objects
    /// reach over the seam that a point move meets, in one pass over those listed on the squares of each
    /// landblock's fine grid the move's box covers: with <see cref="ObjectPass.Walls"/>, the first wall
    /// <paramref name="line"/> (landblock-local to <paramref name="entry"/>) crosses, as
    /// <see cref="FirstCrossing(ReadOnlySpan{ObjectSurface}, in StepLine, ref ObjectHit)"/>; with
    /// <see cref="ObjectPass.Floors"/>, the ground raised to the highest object floor under its end no higher than
    /// its height, and whether an object may have a floor there above it (<see cref="ObjectHit.FloorAbove"/>). Into
    /// <paramref name="hit"/>.
    /// </summary>
    public static void AmongOutdoors(ref Neighbourhood lands, LandblockEntry entry, in StepLine line, ObjectPass pass, ref ObjectHit hit)
    {
        AmongOutdoors(entry, in line, pass, ref hit);
        if (lands.ReachInto(entry).Meets(line.Lo, line.Hi))
        {
            AcrossSeams(ref lands, entry, in line, pass, ref hit);
        }
    }

    /// <summary><see cref="AmongOutdoors(ref Neighbourhood, LandblockEntry, in StepLine, ObjectPass, ref ObjectHit)"/> in the neighbours whose objects reach the move.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // out of the common path: only within a neighbour's reach
    private static void AcrossSeams(ref Neighbourhood lands, LandblockEntry entry, in StepLine line, ObjectPass pass, ref ObjectHit hit)
    {
        SeamNeighbours across = Neighbourhood.Across(ref lands, entry, line.Lo, line.Hi);
        while (across.MoveNext())
        {
            AmongOutdoors(across.Current, line.Less(across.Offset), pass, ref hit);
        }
    }

    /// <summary>
    /// As <see cref="AmongOutdoors(ref Neighbourhood, LandblockEntry, in StepLine, ObjectPass, ref ObjectHit)"/>,
    /// the objects of one landblock (the line in its frame). The objects' boxes (<see cref="LandblockEntry.ObjectBoxes"/>)
    /// reject them first, so only an object in reach is read.
    /// </summary>
    public static void AmongOutdoors(LandblockEntry entry, in StepLine line, ObjectPass pass, ref ObjectHit hit)
    {
        // Stryker disable once Statement,Block : with no objects the grid lists none
        if (entry.OutdoorObjects.Length == 0)
        {
            return;
        }

        bool walls = (pass & ObjectPass.Walls) != 0, floors = (pass & ObjectPass.Floors) != 0;
        float h = line.H;
        Vector2 p1 = line.P1;
        ObjectSurface[] objects = entry.OutdoorObjects;
        for (BoxGrid.Cursor near = entry.Objects.Near(line.Lo, line.Hi); near.MoveNext();)
        {
            int i = near.Current;
            ref readonly ObjectBox b = ref entry.ObjectBoxes[i];
            if (walls && Straddles(b.ZMin, b.ZMax, h) && Obstructs(objects[i], in b, in line, ref hit))
            {
                hit.Wall = objects[i];
            }

            if (floors && Boxes.Overlaps(b.FloorMin, b.FloorMax, p1, p1))
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
        AmongOutdoors(ref lands, entry, new StepLine(p, p, feetZ + stepUp), ObjectPass.Floors, ref hit);
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
        float ceiling = /* Stryker disable once Arithmetic : a ground above the feet is above the feet less a step too, and its pass looks up to the same ceiling */ feetZ + stepUp;
        while (/* Stryker disable once Logical : a looser condition runs one more pass, which finds no higher floor and returns */ hit.FloorAbove && hit.GroundZ > feetZ && hit.GroundZ + stepUp > ceiling)
        {
            ceiling = hit.GroundZ + stepUp;
            float ground = hit.GroundZ;
            hit.FloorAbove = /* Stryker disable once Boolean : one more pass, which finds no higher floor and returns */ false;
            AmongOutdoors(ref lands, entry, new StepLine(p, p, ceiling), ObjectPass.Floors, ref hit);
            // Stryker disable once Statement,Block : the loop's condition then fails: the ground plus the step is the ceiling
            if (hit.GroundZ == ground)
            {
                return;
            }
        }
    }

    /// <summary>
    /// Whether <paramref name="line"/> crosses a wall of <paramref name="o"/> before <c>hit.T</c>, or one of its floors rising
    /// through it; the object's height range rejects it first, then its walls' bounds the walls (its floors' bounds, grown
    /// by the edge tolerance as the floors are sampled, are tested by <see cref="ObjectSurface.RisesThrough"/>).
    /// </summary>
    private static bool Crosses(ObjectSurface o, in StepLine line, ref ObjectHit hit)
    {
        float h = line.H;
        if (!Straddles(o.BoundsMin.Z, o.BoundsMax.Z, h))
        {
            return false;
        }

        bool met = Boxes.Overlaps(o.Walls.Min, o.Walls.Max, line.Lo, line.Hi) && line.FirstCrossing(o.Walls, ref hit);
        hit.Rises &= !met;
        if (o.RisesThrough(in line, ref hit.T, ref hit.Normal))
        {
            (met, hit.Rises, hit.Cylinder) = (true, true, /* Stryker disable once Boolean : read only when the hit is not a rise; a wall met later sets it again */ false);
        }

        return met;
    }

    /// <summary>
    /// What of outdoor object <paramref name="o"/> (its box <paramref name="b"/>) <paramref name="line"/> meets first, into
    /// <paramref name="hit"/>: a wall it crosses, or a floor rising through the line (<see cref="ObjectSurface.RisesThrough"/>).
    /// True when it is met before what <paramref name="hit"/> held.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool Obstructs(ObjectSurface o, in ObjectBox b, in StepLine line, ref ObjectHit hit)
    {
        Vector2 lo = line.Lo, hi = line.Hi;
        bool met = Boxes.Overlaps(b.WallMin, b.WallMax, lo, hi) && line.FirstCrossing(o.Walls, ref hit);
        hit.Rises &= !met;
        if (Boxes.Overlaps(b.FloorMin, b.FloorMax, lo, hi) && o.RisesThrough(in line, ref hit.T, ref hit.Normal))
        {
            (met, hit.Rises, hit.Cylinder) = (true, true, /* Stryker disable once Boolean : read only when the hit is not a rise; a wall met later sets it again */ false);
        }

        return met;
    }

    /// <summary>Whether height <paramref name="h"/> lies strictly between <paramref name="zMin"/> and <paramref name="zMax"/> (metres): a line level with an object's bottom or top passes it.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static bool Straddles(float zMin, float zMax, float h) => zMin < h && zMax > h;
}

/// <summary>What an outdoor pass among objects looks for (<see cref="ObjectQueries.AmongOutdoors(LandblockEntry, in StepLine, ObjectPass, ref ObjectHit)"/>).</summary>
[Flags]
internal enum ObjectPass
{
    /// <summary>The first wall the step line crosses.</summary>
    Walls = 1,

    /// <summary>The highest floor under the line's end no higher than its height.</summary>
    Floors = 2,

    /// <summary>Both.</summary>
    Both = Walls | Floors,
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

    /// <summary>Whether what <see cref="Wall"/> met first is one of its cylinders.</summary>
    public bool Cylinder;

    /// <summary>Whether what <see cref="Wall"/> met first is one of its floors rising through the step line (a rise too high), not a wall.</summary>
    public bool Rises;
    public float GroundZ;
    public ObjectSurface? Floor;

    /// <summary>Whether an object whose floors' bounds hold the end point reaches above the height a floors pass looked up to: a higher floor may be there.</summary>
    public bool FloorAbove;

    /// <summary>Nothing met yet, over ground at <paramref name="groundZ"/>.</summary>
    public static ObjectHit Over(float groundZ) => new() { T = 2f, GroundZ = groundZ };
}
