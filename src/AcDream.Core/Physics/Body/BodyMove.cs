using System.Numerics;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// One sweep of a body among walls: a disc of contact radius <see cref="Radius"/> whose centre moves from
/// <see cref="P"/> along <see cref="D"/>, meeting walls where they reach between <see cref="ZLow"/> and
/// <see cref="ZHigh"/>; a wall's end it comes no nearer to than <see cref="Graze"/> is grazed, not met, and
/// rounding may leave it up to <see cref="Sink"/> inside its contact radius (see <see cref="BodySweep.Slide"/>).
/// Landblock-local metres of the mover's landblock.
/// </summary>
internal readonly record struct BodyMove(Vector2 P, Vector2 D, float Radius, float Graze, float Sink, float ZLow, float ZHigh)
{
    /// <summary>A move of a body of contact radius <paramref name="radius"/> whose rounding sink is <paramref name="sink"/>: its graze is the radius less the sink and the contact tolerance.</summary>
    public static BodyMove Of(Vector2 p, Vector2 d, float radius, float sink, float zLow, float zHigh) =>
        new(p, d, radius, radius - sink - PhysicsConstants.ContactTolerance, sink, zLow, zHigh);

    /// <summary>This move's body and band, from <paramref name="p"/> along <paramref name="d"/>.</summary>
    public BodyMove At(Vector2 p, Vector2 d) => this with { P = p, D = d };
}

/// <summary>
/// The running answer of a sweep: the earliest contact so far (<see cref="T"/>, the fraction of the move,
/// 1 for none; <see cref="Normal"/>, the wall's unit normal seen from above, pointing at the body) and the
/// deepest overlap at the start (<see cref="Depth"/> metres, with <see cref="Outward"/>, the unit normal out of it, and
/// <see cref="Lift"/>, how far the slide moves out of it besides).
/// </summary>
internal struct WallHit
{
    public float T;
    public Vector2 Normal;
    public float Depth;
    public Vector2 Outward;

    /// <summary>
    /// Where the deepest overlap is a mover's solid the body starts in or deep against (<see cref="MoverSolid"/>, which
    /// then meets it at the start too): what the slide adds to the move past that contact, out of the solid by the sink,
    /// so that the rounding of the answer does not sink the body deeper frame after frame; else zero.
    /// </summary>
    public Vector2 Lift;

    /// <summary>Whose walls are being swept now (set by the sweep before each cell's or object's walls).</summary>
    public WallSource Current;

    /// <summary>Whose wall the contact so far is (<see cref="T"/>), and whose the deepest overlap (<see cref="Depth"/>).</summary>
    public WallSource Source;

    public WallSource DeepSource;

    /// <summary>No contact and no overlap yet.</summary>
    public static WallHit None => new() { T = 1f };

    /// <summary>
    /// A contact at fraction <paramref name="t"/> with unit normal <paramref name="normal"/>: kept when earlier
    /// than the one so far, or as early with a normal that comes first in a fixed order (larger X, then larger
    /// Y). The nearest contact therefore does not depend on the order in which walls are swept.
    /// </summary>
    public void Contact(float t, Vector2 normal)
    {
        if (t < T || (t == T && t < 1f && Precedes(normal, Normal)))
        {
            (T, Normal, Source) = (t, normal, Current);
        }
    }

    /// <summary>
    /// An overlap of <paramref name="depth"/> metres at the start, out along <paramref name="outward"/> (with the
    /// <paramref name="lift"/> of a solid the body is inside): kept when deeper (ties as <see cref="Contact"/>).
    /// </summary>
    public void Overlap(float depth, Vector2 outward, Vector2 lift = default)
    {
        if (depth > Depth || (depth == Depth && depth > 0f && Precedes(outward, Outward)))
        {
            (Depth, Outward, DeepSource, Lift) = (depth, outward, Current, lift);
        }
    }

    private static bool Precedes(Vector2 a, Vector2 b) => a.X > b.X || (a.X == b.X && a.Y > b.Y);
}

/// <summary>Whose wall a body met: what it is and its id (a cell's, or an object's GfxObj or Setup id).</summary>
internal readonly record struct WallSource(SurfaceKind Kind, uint Id)
{
    /// <summary>An object's walls: its shell's, or an object's.</summary>
    public static WallSource Of(ObjectSurface o) => new(o.IsBuilding ? SurfaceKind.BuildingShell : SurfaceKind.ObjectWall, o.ObjectId);
}

/// <summary>What a body's path holds besides its corner points: how many corners, and what it touched.</summary>
internal struct BodyPath
{
    /// <summary>How many corner points are used (1 + legs); the first is the start.</summary>
    public int Count;

    /// <summary>Walls touched.</summary>
    public int Contacts;

    /// <summary>The last wall touched: its unit normal seen from above, pointing at the body.</summary>
    public Vector2 Normal;

    /// <summary>Whose the last wall touched is.</summary>
    public WallSource Wall;
}
