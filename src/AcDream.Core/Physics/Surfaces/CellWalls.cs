using System.Numerics;
using System.Runtime.Intrinsics;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>
/// One wall of a cell for the body: a physics polygon that is not a floor, landblock-local, with
/// its height range and its bounds seen from above. Its vertices are a slice of
/// <see cref="CellWalls.Vertices"/>.
/// </summary>
/// <remarks>
/// <para>
/// A vertical rectangle (every vertex at one of the two ends along the wall and at its lowest or
/// highest Z: most real walls) is the same segment <see cref="A"/>–<see cref="B"/> seen from above at
/// every height it spans, so it needs no cutting to a band (<see cref="IsUpright"/>).
/// </para>
/// <para>
/// A round wall (an object's cylinder) is upright with <see cref="A"/> = <see cref="B"/> = its axis
/// and <see cref="Radius"/> > 0: the body keeps the sum of the two radii from the axis. Planar walls
/// have radius 0.
/// </para>
/// </remarks>
internal readonly record struct WallPolygon(int First, int Count, float ZMin, float ZMax, Vector2 Min, Vector2 Max, bool IsUpright, Vector2 A, Vector2 B, float Radius = 0f);

/// <summary>
/// Bounds of a set of walls, landblock-local metres: seen from above (<see cref="Min"/>–<see cref="Max"/>)
/// and in height (<see cref="ZMin"/>–<see cref="ZMax"/>); empty (min &gt; max) for none.
/// </summary>
internal readonly record struct WallBounds(Vector2 Min, Vector2 Max, float ZMin, float ZMax)
{
    /// <summary>These bounds and <paramref name="other"/>'s together.</summary>
    public WallBounds With(WallBounds other) =>
        new(Vector2.Min(Min, other.Min), Vector2.Max(Max, other.Max), MathF.Min(ZMin, other.ZMin), MathF.Max(ZMax, other.ZMax));

    /// <summary>Whether they meet <paramref name="box"/> moved by −<paramref name="offset"/> (into their frame): seen from above and in its band.</summary>
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    public bool Meets(in WallBox box, Vector2 offset) =>
        Min.X <= box.Hi.X - offset.X && Max.X >= box.Lo.X - offset.X && Min.Y <= box.Hi.Y - offset.Y && Max.Y >= box.Lo.Y - offset.Y
        && ZMax > box.ZLow && ZMin < box.ZHigh;
}

/// <summary>
/// The walls of one cell, built once when the cell is: every physics polygon that is not a floor
/// (walls, ceilings, steep faces), except those that cover one of the cell's own portals (some
/// doorways carry a solid physics polygon in the opening), in landblock-local metres.
/// </summary>
internal sealed class CellWalls
{
    /// <summary>No walls.</summary>
    public static readonly CellWalls None = new([], []);

    private CellWalls(WallPolygon[] polygons, Vector3[] vertices, bool steep = false)
    {
        Polygons = polygons;
        Vertices = vertices;
        HasSteep = steep;
        Extents = new WallExtent[polygons.Length];
        for (int i = 0; i < polygons.Length; i++)
        {
            Extents[i] = new WallExtent(polygons[i]);
        }

        if (polygons.Length == 0)
        {
            Min = new Vector2(float.MaxValue);
            Max = new Vector2(float.MinValue);
            (ZMin, ZMax) = (float.MaxValue, float.MinValue);
            return;
        }

        Vector2 min = polygons[0].Min, max = polygons[0].Max;
        float zMin = polygons[0].ZMin, zMax = polygons[0].ZMax;
        foreach (WallPolygon w in polygons)
        {
            min = Vector2.Min(min, w.Min);
            max = Vector2.Max(max, w.Max);
            zMin = MathF.Min(zMin, w.ZMin);
            zMax = MathF.Max(zMax, w.ZMax);
        }

        (Min, Max, ZMin, ZMax) = (min, max, zMin, zMax);
    }

    public WallPolygon[] Polygons { get; }

    /// <summary>Whether a wall is a face too steep to stand on but not to land on, facing up (unit normal Z between <see cref="PhysicsConstants.LandingZ"/> and <see cref="PhysicsConstants.FloorZ"/>): a fall may land on it.</summary>
    public bool HasSteep { get; }

    public Vector3[] Vertices { get; }

    /// <summary>Each polygon's bounds, packed for the sweep's first test (<see cref="WallExtent.Meets"/>), in <see cref="Polygons"/>' order.</summary>
    public WallExtent[] Extents { get; }

    /// <summary>Bounds of all the walls seen from above (empty when there are none).</summary>
    public Vector2 Min { get; private set; }

    public Vector2 Max { get; private set; }

    /// <summary>The lowest and highest Z of all the walls (empty when there are none).</summary>
    public float ZMin { get; private set; }

    public float ZMax { get; private set; }

    /// <summary>
    /// Builds the walls from the placed physics polygons (each with its winding normal), leaving out
    /// floors and any polygon that lies in the plane of one of <paramref name="portals"/> with its
    /// centre inside the opening.
    /// </summary>
    /// <param name="cell">Names the cell or object in messages.</param>
    /// <param name="polygons">The placed physics polygons.</param>
    /// <param name="portals">The cell's portals (none for an object).</param>
    /// <param name="cylinders">Round walls: each standing on its base, landblock-local.</param>
    /// <param name="argument">The argument a bad polygon came in.</param>
    /// <exception cref="ArgumentException">A wall polygon has more than <see cref="PhysicsConstants.MaxWallPolygonVertices"/> vertices.</exception>
    public static CellWalls Build(
        string cell, List<(ushort Id, Vector3[] Vertices, Vector3 Normal)> polygons, PortalShape[] portals,
        List<(Vector3 Base, float Radius, float Height)> cylinders, string argument)
    {
        var walls = new List<WallPolygon>();
        var vertices = new List<Vector3>();
        bool steep = false;
        foreach ((ushort id, Vector3[] v, Vector3 normal) in polygons)
        {
            if (normal == Vector3.Zero || normal.Z >= PhysicsConstants.FloorZ || CoversPortal(v, portals))
            {
                continue; // no area, a floor, or a doorway's cover
            }

            if (v.Length > PhysicsConstants.MaxWallPolygonVertices)
            {
                throw new ArgumentException(
                    $"{cell}: physics polygon {id} has {v.Length} vertices; a wall may have at most {PhysicsConstants.MaxWallPolygonVertices}.",
                    argument);
            }

            float zMin = float.MaxValue, zMax = float.MinValue;
            Vector2 min = new(float.MaxValue), max = new(float.MinValue);
            foreach (Vector3 p in v)
            {
                zMin = MathF.Min(zMin, p.Z);
                zMax = MathF.Max(zMax, p.Z);
                min = Vector2.Min(min, new Vector2(p.X, p.Y));
                max = Vector2.Max(max, new Vector2(p.X, p.Y));
            }

            steep |= normal.Z > PhysicsConstants.LandingZ;
            (bool upright, Vector2 a, Vector2 b) = Upright(v, normal, zMin, zMax);
            walls.Add(new WallPolygon(vertices.Count, v.Length, zMin, zMax, min, max, upright, a, b));
            vertices.AddRange(v);
        }

        foreach ((Vector3 b, float r, float h) in cylinders)
        {
            if (r > 0f && h > 0f)
            {
                var axis = new Vector2(b.X, b.Y);
                walls.Add(new WallPolygon(vertices.Count, 0, b.Z, b.Z + h, axis - new Vector2(r), axis + new Vector2(r), true, axis, axis, r));
            }
        }

        return walls.Count == 0 ? None : new CellWalls([.. walls], [.. vertices], steep);
    }

    /// <summary>A copy with arrays of its own, for <see cref="PlaceFrom"/> to write into.</summary>
    public CellWalls Copy() => new((WallPolygon[])Polygons.Clone(), (Vector3[])Vertices.Clone(), HasSteep);

    /// <summary>
    /// Writes into this copy (of <paramref name="local"/>) the walls of <paramref name="local"/> turned about Z by the
    /// angle whose cosine and sine are given and then moved by <paramref name="origin"/>: each coordinate computed in
    /// double and rounded once. A turn about Z keeps an upright wall upright and a cylinder a cylinder. Only for a copy
    /// no reader holds.
    /// </summary>
    public void PlaceFrom(CellWalls local, double cos, double sin, Vector3 origin)
    {
        Vector3[] from = local.Vertices;
        for (int i = 0; i < from.Length; i++)
        {
            Vector2 xy = Turn(new Vector2(from[i].X, from[i].Y), cos, sin, origin);
            Vertices[i] = new Vector3(xy, (float)((double)origin.Z + from[i].Z));
        }

        Vector2 min = new(float.MaxValue), max = new(float.MinValue);
        float zMin = float.MaxValue, zMax = float.MinValue;
        for (int i = 0; i < Polygons.Length; i++)
        {
            WallPolygon w = local.Polygons[i];
            Vector2 a = w.IsUpright ? Turn(w.A, cos, sin, origin) : default, b = w.IsUpright && w.Radius == 0f ? Turn(w.B, cos, sin, origin) : a;
            Vector2 lo = a - new Vector2(w.Radius), hi = a + new Vector2(w.Radius);
            if (w.Radius == 0f)
            {
                (lo, hi) = (new Vector2(float.MaxValue), new Vector2(float.MinValue));
                foreach (Vector3 v in Vertices.AsSpan(w.First, w.Count))
                {
                    (lo, hi) = (Vector2.Min(lo, new Vector2(v.X, v.Y)), Vector2.Max(hi, new Vector2(v.X, v.Y)));
                }
            }

            var placed = w with
            {
                ZMin = (float)((double)origin.Z + w.ZMin), ZMax = (float)((double)origin.Z + w.ZMax), Min = lo, Max = hi,
                A = a, B = b,
            };
            Polygons[i] = placed;
            Extents[i] = new WallExtent(placed);
            (min, max, zMin, zMax) = (Vector2.Min(min, lo), Vector2.Max(max, hi), MathF.Min(zMin, placed.ZMin), MathF.Max(zMax, placed.ZMax));
        }

        (Min, Max, ZMin, ZMax) = (min, max, zMin, zMax);
    }

    private static Vector2 Turn(Vector2 p, double cos, double sin, Vector3 origin) =>
        new((float)(origin.X + ((cos * p.X) - (sin * p.Y))), (float)(origin.Y + ((sin * p.X) + (cos * p.Y))));

    /// <summary>
    /// Whether the polygon is a vertical rectangle: its normal horizontal (within 1e-4) and every vertex
    /// at one of its two ends along the wall and at its lowest or highest Z (within
    /// <see cref="PhysicsConstants.EdgeTolerance"/>); then the ends' points seen from above.
    /// </summary>
    private static (bool Upright, Vector2 A, Vector2 B) Upright(Vector3[] v, Vector3 normal, float zMin, float zMax)
    {
        var along = new Vector2(-normal.Y, normal.X);
        if (MathF.Abs(normal.Z) > 1e-4f || along == Vector2.Zero)
        {
            return (false, default, default);
        }

        along = Vector2.Normalize(along);
        int first = 0, last = 0;
        for (int i = 1; i < v.Length; i++)
        {
            float at = Vector2.Dot(along, new Vector2(v[i].X, v[i].Y));
            first = at < Vector2.Dot(along, new Vector2(v[first].X, v[first].Y)) ? i : first;
            last = at > Vector2.Dot(along, new Vector2(v[last].X, v[last].Y)) ? i : last;
        }

        var a = new Vector2(v[first].X, v[first].Y);
        var b = new Vector2(v[last].X, v[last].Y);
        const float tol = PhysicsConstants.EdgeTolerance;
        foreach (Vector3 p in v)
        {
            var xy = new Vector2(p.X, p.Y);
            bool atAnEnd = Vector2.DistanceSquared(xy, a) <= tol * tol || Vector2.DistanceSquared(xy, b) <= tol * tol;
            bool atTopOrBottom = MathF.Abs(p.Z - zMin) <= tol || MathF.Abs(p.Z - zMax) <= tol;
            if (!atAnEnd || !atTopOrBottom)
            {
                return (false, default, default);
            }
        }

        return (true, a, b);
    }

    private static bool CoversPortal(Vector3[] polygon, PortalShape[] portals)
    {
        Vector3 centre = Vector3.Zero;
        foreach (Vector3 p in polygon)
        {
            centre += p;
        }

        centre /= polygon.Length;
        foreach (PortalShape portal in portals)
        {
            if (portal.Covers(polygon, centre))
            {
                return true;
            }
        }

        return false;
    }
}

/// <summary>
/// A wall polygon's bounds packed so that one comparison of four lanes tests them against a box seen from above:
/// (min X, min Y, −max X, −max Y) against (box max X, box max Y, −box min X, −box min Y), then the heights. The
/// comparisons are exact (negation is exact), so the test is the same on every instruction set.
/// </summary>
internal readonly struct WallExtent(WallPolygon wall)
{
    private readonly Vector128<float> _xy = Pack(wall.Min, wall.Max);
    private readonly float _zMin = wall.ZMin;
    private readonly float _zMax = wall.ZMax;

    /// <summary>Bounds <paramref name="min"/>–<paramref name="max"/> seen from above, packed: <c>Vector128.LessThanOrEqualAll(packed, Query(lo, hi))</c> when they meet the box lo–hi.</summary>
    public static Vector128<float> Pack(Vector2 min, Vector2 max) => Vector128.Create(min.X, min.Y, -max.X, -max.Y);

    /// <summary>The box (min X, min Y, max X, max Y) as <see cref="Meets"/> takes it.</summary>
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    public static Vector128<float> Query(Vector2 lo, Vector2 hi) => Vector128.Create(hi.X, hi.Y, -lo.X, -lo.Y);

    /// <summary>Whether the polygon's bounds meet the box (<see cref="Query"/>) seen from above and reach into the band <paramref name="zLow"/>–<paramref name="zHigh"/> (open at both ends).</summary>
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    public bool Meets(Vector128<float> box, float zLow, float zHigh) =>
        Vector128.LessThanOrEqualAll(_xy, box) && _zMax > zLow && _zMin < zHigh;
}
