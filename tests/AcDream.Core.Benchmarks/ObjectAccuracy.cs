using System.Globalization;
using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// <c>--accuracy</c>, the objects' row (issue 11): the floors of the real objects at seeded random
/// placements, as the engine finds them (<see cref="PhysicsEngine.TryGetGround(Vector3, uint, float, out float, out Vector3, out uint)"/>
/// and the end Z of a literal <c>Resolve</c>), against <see cref="ReferenceObjectFloor"/>: each floor
/// polygon's own plane in double precision, from the object's definition.
/// </summary>
internal static class ObjectAccuracy
{
    private const int Placements = 800, Points = 20;

    /// <summary>Points closer than this to a floor polygon's edge (seen from above) are left out: there the tolerance of the edge decides.</summary>
    private const double NearEdge = 1e-3;

    /// <summary>Points with another floor within this of the step's ceiling are left out: which floor is highest under it is a tie.</summary>
    private const double NearCeiling = 1e-3;

    private const float Step = 0.5f;

    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    public static void Run(TextWriter o)
    {
        var random = new Random(5);
        Dictionary<uint, GfxObj> gfxObjs = ObjectWorld.GfxObjs();
        uint[] ids = [.. gfxObjs.Keys.Where(id => id != ObjectWorld.TrunkId).Order()];
        var engine = new PhysicsEngine(World.Holtburg);
        var terrain = new TerrainSurface(new byte[81], World.ConstantTable(0f), World.Holtburg);
        double groundMax = 0, groundSum = 0, moveMax = 0, moveSum = 0;
        int ground = 0, groundMissed = 0, moved = 0, stopped = 0, nearEdge = 0, nearCeiling = 0, noStart = 0, tilted = 0;
        var perObject = new SortedDictionary<uint, (int Points, double Max)>();
        for (int p = 0; p < Placements; p++)
        {
            // An object somewhere over the landblock (x, y 10..182 m, z 20..150 m over flat terrain at 0),
            // turned by a random yaw, half of them tilted up to 5° about a random horizontal axis, the
            // stored quaternion slightly non-unit.
            GfxObj gfxObj = gfxObjs[ids[random.Next(ids.Length)]];
            var origin = new Vector3(10f + (random.NextSingle() * 172f), 10f + (random.NextSingle() * 172f), 20f + (random.NextSingle() * 130f));
            Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, random.NextSingle() * 2f * MathF.PI);
            if (p % 2 == 0)
            {
                Vector3 axis = Vector3.Normalize(new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, 0f));
                q = Quaternion.Concatenate(Quaternion.CreateFromAxisAngle(axis, random.NextSingle() * 5f * MathF.PI / 180f), q);
                tilted++;
            }

            float scale = 1f + ((random.NextSingle() - 0.5f) * 0.002f);
            var frame = new Frame { Origin = origin, Orientation = new Quaternion(q.X * scale, q.Y * scale, q.Z * scale, q.W * scale) };
            engine.AddLandblock(World.Holtburg, terrain, [], [new ObjectSurface(gfxObj, frame, 0)]);
            var reference = new ReferenceObjectFloor(gfxObj, frame);
            for (int i = 0; i < Points; i++)
            {
                (double x, double y, int floor) = reference.RandomPoint(random);
                float fx = (float)x, fy = (float)y;
                float feet = (float)reference.PlaneZ(floor, fx, fy);
                uint cell = 0xA9B40000u | World.OutdoorCell(fx, fy);
                if (reference.EdgeDistance(fx, fy) < NearEdge)
                {
                    nearEdge++;
                    continue;
                }

                if (reference.AtRest(fx, fy, feet, Step, NearCeiling) is not double want)
                {
                    nearCeiling++;
                    continue;
                }

                if (!engine.TryGetGround(new Vector3(fx, fy, feet), cell, Step, out float got, out _, out uint objectId) || objectId != gfxObj.Id)
                {
                    groundMissed++;
                    continue;
                }

                double e = Math.Abs(got - want);
                (groundMax, groundSum, ground) = (Math.Max(groundMax, e), groundSum + e, ground + 1);
                perObject[gfxObj.Id] = perObject.TryGetValue(gfxObj.Id, out var a) ? (a.Points + 1, Math.Max(a.Max, e)) : (1, e);

                // Resolve: a literal 2 cm move ending at the point, from a start on a floor of the object.
                Vector3 delta = World.RandomDelta(random, 0.02f, 0.02f);
                float sx = fx - delta.X, sy = fy - delta.Y;
                if (reference.EdgeDistance(sx, sy) < NearEdge || reference.AtRest(sx, sy, feet, Step, NearCeiling) is not double startZ
                    || reference.AtRest(sx, sy, startZ, Step, NearCeiling) != startZ)
                {
                    noStart++;
                    continue;
                }

                var start = new Vector3(sx, sy, (float)startZ);
                ResolveResult r = engine.Resolve(start, 0xA9B40000u | World.OutdoorCell(sx, sy), delta, Step);
                if (r.Outcome != ResolveOutcome.Moved)
                {
                    stopped++;
                    continue;
                }

                if (reference.EdgeDistance(r.Position.X, r.Position.Y) < NearEdge
                    || reference.AtRest(r.Position.X, r.Position.Y, start.Z, Step, NearCeiling) is not double wantEnd)
                {
                    noStart++;
                    continue;
                }

                double m = Math.Abs(r.Position.Z - wantEnd);
                (moveMax, moveSum, moved) = (Math.Max(moveMax, m), moveSum + m, moved + 1);
            }
        }

        o.WriteLine($"## Objects (issue 11): object floors vs a double-precision reference ({Placements} random placements of the real objects × {Points} points)");
        o.WriteLine();
        o.WriteLine("Each placement is one of the four real GfxObjs of `Fixtures/objects/` (cottage shell 0x01000A2B, small building 0x01000F69, stair");
        o.WriteLine($"pieces 0x01000AC5 and 0x01000ACA) over flat terrain at z 0, at x, y 10–182 m, z 20–150 m, a random yaw, {tilted} of them tilted up to 5°,");
        o.WriteLine("the stored quaternion up to 0.1 % off unit. Each point is a random point of a random floor polygon (its fan triangles, uniform");
        o.WriteLine("barycentric), rounded to float; the feet stand at that polygon's reference Z there, the step is 0.5 m. The reference");
        o.WriteLine("(`ReferenceObjectFloor.cs`) places the vertices in double (normalised quaternion), takes each polygon's Newell normal and");
        o.WriteLine("the plane through its vertices' mean, keeps the polygons with normal Z ≥ FloorZ, and answers the highest plane Z under");
        o.WriteLine("the point no higher than feet + step. Left out: points within 1 mm of a floor polygon's edge, and points where a floor lies within 1 mm of");
        o.WriteLine("feet + step (a tie). `Resolve`: a literal 2 cm move ending at the point from a start on the object's floor, its end Z against");
        o.WriteLine("the reference at the end position.");
        o.WriteLine();
        o.WriteLine("| measure | value |");
        o.WriteLine("| --- | ---: |");
        o.WriteLine($"| `TryGetGround` points compared (the object's floor found) | {ground} |");
        o.WriteLine($"| max \\|engine − reference\\| Z, `TryGetGround` (m) | {E(groundMax)} |");
        o.WriteLine($"| mean \\|engine − reference\\| Z, `TryGetGround` (m) | {E(groundSum / Math.Max(ground, 1))} |");
        o.WriteLine($"| points where `TryGetGround` found no floor of the object | {groundMissed} |");
        o.WriteLine($"| `Resolve` end points compared (outcome `Moved`) | {moved} |");
        o.WriteLine($"| max \\|engine − reference\\| Z, `Resolve` end (m) | {E(moveMax)} |");
        o.WriteLine($"| mean \\|engine − reference\\| Z, `Resolve` end (m) | {E(moveSum / Math.Max(moved, 1))} |");
        o.WriteLine($"| `Resolve` moves stopped (an object wall at the feet + step) | {stopped} |");
        o.WriteLine($"| left out: within 1 mm of an edge / a floor within 1 mm of the ceiling / start or end off the floors | {nearEdge} / {nearCeiling} / {noStart} |");
        o.WriteLine($"| per object: points, max error (m) | {string.Join("; ", perObject.Select(kv => $"0x{kv.Key:X8}: {kv.Value.Points}, {E(kv.Value.Max)}"))} |");
        o.WriteLine();
        Summary = (ground, groundMax, groundSum / Math.Max(ground, 1), moved, moveMax, moveSum / Math.Max(moved, 1));
    }

    /// <summary>After <see cref="Run"/>: the points and errors of the two comparisons.</summary>
    public static (int GroundPoints, double GroundMax, double GroundMean, int MovePoints, double MoveMax, double MoveMean) Summary { get; private set; }

    private static string E(double v) => v.ToString("0.00e+0", Inv);
}
