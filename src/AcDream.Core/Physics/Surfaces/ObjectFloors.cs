using System.Numerics;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>
/// Where a mover comes to rest among the floors of a list of objects (those standing in one cell), at a
/// point seen from above: landblock-local metres, allocation-free.
/// </summary>
internal static class ObjectFloors
{
    /// <summary>
    /// Raises <paramref name="rest"/> to the highest floor of <paramref name="objects"/> under <paramref name="p"/> that is
    /// no higher than <paramref name="ceilingZ"/>, when that is above it (or when it has no floor yet). Returns whether it
    /// raised it; then <see cref="FloorRest.Object"/> is the object's index.
    /// </summary>
    public static bool Raise(ReadOnlySpan<ObjectSurface> objects, Vector2 p, float ceilingZ, ref FloorRest rest)
    {
        int raised = -1;
        for (int i = 0; i < objects.Length; i++)
        {
            if (objects[i].TryFloorBelow(p.X, p.Y, ceilingZ, out float floor) && (!rest.Found || floor > rest.Z))
            {
                (rest.Z, rest.Found, raised) = (floor, true, i);
            }
        }

        if (raised >= 0)
        {
            rest.Object = raised;
        }

        return raised >= 0;
    }

    /// <summary>
    /// The ground a mover with its feet at <paramref name="feetZ"/> and step <paramref name="stepUp"/> comes to rest on
    /// at <paramref name="p"/>, from <paramref name="rest"/> (the floor under it, if found): raised to the highest floor
    /// of <paramref name="objects"/> no more than the step above the feet, and again from there while that lifts it
    /// (a step from the floor it climbed, a tread from a tread), until no floor within a step of where it stands is
    /// higher. What makes standing still on the answer give the answer again. True when an object's floor raised it
    /// (<see cref="FloorRest.Object"/> is then that object's index).
    /// </summary>
    public static bool RaiseToRest(ReadOnlySpan<ObjectSurface> objects, Vector2 p, float feetZ, float stepUp, ref FloorRest rest)
    {
        rest.Object = -1;
        float ceiling = (rest.Found && rest.Z > feetZ ? rest.Z : feetZ) + stepUp;
        while (Raise(objects, p, ceiling, ref rest))
        {
            if (!(rest.Z > feetZ && rest.Z + stepUp > ceiling))
            {
                break;
            }

            ceiling = rest.Z + stepUp;
        }

        return rest.Object >= 0;
    }
}

/// <summary>The ground a mover comes to rest on: its Z (metres), whether there is one, and the object whose floor it is (−1: none).</summary>
internal struct FloorRest
{
    public float Z;
    public bool Found;
    public int Object;

    /// <summary>A floor at <paramref name="z"/> when <paramref name="found"/>; no object's.</summary>
    public FloorRest(float z, bool found) => (Z, Found, Object) = (z, found, -1);
}
