using System.Numerics;
using AcDream.Core.Dat;

namespace AcDream.Core.Physics;

/// <summary>
/// The solid shape of a mover (<see cref="MoverRegistry"/>) in its own frame: metres, the origin at the mover's position, Z up.
/// Built once and shared by any number of movers. Only walls: the physics polygons that are not floors (normal Z below
/// <see cref="PhysicsConstants.FloorZ"/>) and upright cylinders; a body does not stand on a mover.
/// </summary>
public sealed class MoverShape
{
    private static readonly Frame Own = new();

    private MoverShape(CellWalls walls, string what, string argument)
    {
        if (walls.Polygons.Length == 0)
        {
            throw new ArgumentException($"{what}: no walls or cylinders; a mover must be something a body can meet.", argument);
        }

        Walls = walls;
        float reach = 0f;
        foreach (WallPolygon w in walls.Polygons)
        {
            reach = MathF.Max(reach, w.Radius > 0f ? w.A.Length() + w.Radius : 0f);
        }

        foreach (Vector3 v in walls.Vertices)
        {
            reach = MathF.Max(reach, new Vector2(v.X, v.Y).Length());
        }

        if (!(reach <= PhysicsConstants.MaxMoverReach))
        {
            throw new ArgumentException($"{what}: reaches {reach} m from its origin; a mover may reach at most {PhysicsConstants.MaxMoverReach} m.", argument);
        }

        Reach = reach;
    }

    /// <summary>
    /// The polygons of <paramref name="gfxObj"/> (its own frame) that are walls, and none of its floors: a door's slab, a
    /// cart.
    /// </summary>
    /// <exception cref="ArgumentException">It has no walls, or they reach more than <see cref="PhysicsConstants.MaxMoverReach"/> from its origin, or its data is not a model (as for <see cref="ObjectSurface"/>).</exception>
    public MoverShape(GfxObj gfxObj)
        : this(new ObjectSurface(gfxObj, Own, 0).Walls, $"GfxObj 0x{gfxObj?.Id:X8}", nameof(gfxObj))
    {
    }

    /// <summary>
    /// The walls of <paramref name="setup"/> in its default pose: its parts' physics polygons, or else its cylinders (the
    /// game's shape choice for a creature), as a static object's.
    /// </summary>
    /// <exception cref="ArgumentException">As for <see cref="MoverShape(GfxObj)"/>.</exception>
    public MoverShape(Setup setup, IReadOnlyDictionary<uint, GfxObj> gfxObjs)
        : this(new ObjectSurface(setup, gfxObjs, Own, 0).Walls, $"Setup 0x{setup?.Id:X8}", nameof(setup))
    {
    }

    private MoverShape(float radius, float height)
        : this(CellWalls.Build("cylinder", [], [], [(Vector3.Zero, radius, height)], "radius"), "cylinder", "radius")
    {
        CylinderBody = new MoverBody(radius, height);
    }

    /// <summary>The cylinder's radius and height (metres) when this shape was built by <see cref="Cylinder"/>; null for a model's walls.</summary>
    public MoverBody? CylinderBody { get; }

    /// <summary>How far its walls reach from its origin, seen from above, metres.</summary>
    public float Reach { get; }

    /// <summary>Its walls in its own frame.</summary>
    internal CellWalls Walls { get; }

    /// <summary>An upright cylinder standing on the origin (a creature: the game's human is 0.48 m by 1.835 m).</summary>
    /// <param name="radius">Metres, &gt; 0 and finite.</param>
    /// <param name="height">Metres, &gt; 0 and finite.</param>
    /// <exception cref="ArgumentOutOfRangeException">Either is not a finite length &gt; 0 (names which).</exception>
    public static MoverShape Cylinder(float radius, float height)
    {
        if (!(float.IsFinite(radius) && radius > 0f && radius <= PhysicsConstants.MaxMoverReach))
        {
            throw new ArgumentOutOfRangeException(nameof(radius), radius, $"a cylinder's radius must be finite, > 0 m and at most {PhysicsConstants.MaxMoverReach} m.");
        }

        if (!(float.IsFinite(height) && height > 0f))
        {
            throw new ArgumentOutOfRangeException(nameof(height), height, "a cylinder's height must be finite and > 0 m.");
        }

        return new MoverShape(radius, height);
    }
}
