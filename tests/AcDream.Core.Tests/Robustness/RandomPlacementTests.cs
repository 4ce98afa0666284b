using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Behavior;
using AcDream.Testing;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Seeded random placements of the real objects, against a double-precision reference built from the
/// objects' own definitions; and random walks around the cottage's shell (without its cells), which
/// may cross its outline only through its two ground-level doors.
/// </summary>
public class RandomPlacementTests(ITestOutputHelper output)
{
    private const uint Landblock = 0x4C5DFFFF;
    private const uint Outdoor = 0x4C5D0000;
    private const float TerrainZ = 50f;

    private static readonly uint[] Models = [ObjectPlacements.StairPiece, 0x01000ACA, ObjectPlacements.SmallBuilding, ObjectPlacements.CottageShell];

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    public void Every_object_floor_is_found_within_1e_4_of_the_reference(int seed)
    {
        var random = new Random(seed);
        var stabs = new List<Stab>();
        for (int i = 0; i < 24; i++)
        {
            uint id = Models[random.Next(Models.Length)];
            float yaw = (float)(random.NextDouble() * 2 * Math.PI);
            Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw);
            if (random.Next(2) == 0)
            {
                // A small pitch: a tilt of up to 8° about a random horizontal axis.
                float axis = (float)(random.NextDouble() * 2 * Math.PI), tilt = (float)(random.NextDouble() * 8 * Math.PI / 180);
                q = Quaternion.Normalize(Quaternion.CreateFromAxisAngle(new Vector3(MathF.Cos(axis), MathF.Sin(axis), 0f), tilt) * q);
            }

            var origin = new Vector3(20f + (float)(random.NextDouble() * 150), 20f + (float)(random.NextDouble() * 150), TerrainZ + (float)((random.NextDouble() * 3) - 1));
            stabs.Add(new Stab { Id = id, Frame = ObjectKit.At(origin, q) });
        }

        // Some objects overlap on purpose: a stair piece on top of each of the first four.
        for (int i = 0; i < 4; i++)
        {
            Frame f = stabs[i].Frame;
            stabs.Add(new Stab { Id = ObjectPlacements.StairPiece, Frame = ObjectKit.At(f.Origin + new Vector3(0.3f, -0.2f, 0.5f), f.Orientation) });
        }

        var info = new LandBlockInfo { Id = 0x4C5DFFFE, Objects = stabs };
        List<ObjectSurface> objects = ObjectSurface.FromLandblock(Landblock, info, [], RealObjects.GfxObjs, RealObjects.NoSetups);
        // Every polygon facing up steeply enough to be near the walkable limit (the rest can be neither floor nor doubt).
        var floors = stabs.SelectMany(s => ObjectKit.Floors(RealObjects.GfxObjs[s.Id], s.Frame)).Where(f => f.Nz > 0.6).ToList();
        floors.Count(f => f.Walkable).Should().BeGreaterThan(24);

        foreach (PhysicsEngine engine in new[] { new PhysicsEngine(Landblock) })
        {
            engine.AddLandblock(Landblock, TestData.FlatTerrain(TerrainZ, Landblock), [], objects);
            double maxGround = 0, maxResolve = 0, maxMove = 0;
            int onObjects = 0, compared = 0, moves = 0;
            foreach (ObjectSurface o in objects)
            {
                for (int k = 0; k < 120; k++)
                {
                    double x = o.BoundsMin.X + (random.NextDouble() * (o.BoundsMax.X - o.BoundsMin.X));
                    double y = o.BoundsMin.Y + (random.NextDouble() * (o.BoundsMax.Y - o.BoundsMin.Y));
                    var p = new Vector3((float)x, (float)y, o.BoundsMin.Z + (float)(random.NextDouble() * (o.BoundsMax.Z - o.BoundsMin.Z + 1)));
                    float step = (float)(random.NextDouble() * 1.5);
                    double? expected = ObjectKit.AtRest(floors, p.X, p.Y, p.Z, step, TerrainZ);
                    if (expected is not double want)
                    {
                        continue;
                    }

                    string what = $"seed {seed}: feet {p:R}, step {step:R}";
                    engine.TryGetGround(p, Outdoor, step, out float z, out Vector3 normal, out uint objectId).Should().BeTrue(what);
                    double error = Math.Abs(z - want);
                    error.Should().BeLessThan(1e-4, $"{what}: TryGetGround {z:R}, reference {want:R}");
                    (objectId != 0).Should().Be(want > TerrainZ, $"{what}: object 0x{objectId:X8}, reference {want:R}");
                    normal.Z.Should().BeGreaterThanOrEqualTo(PhysicsConstants.FloorZ - 1e-3f, $"{what}: {normal}");
                    maxGround = Math.Max(maxGround, error);
                    onObjects += objectId != 0 ? 1 : 0;
                    compared++;

                    ResolveResult r = engine.Resolve(p, Outdoor, Vector3.Zero, step);
                    r.Position.Z.Should().BeApproximately((float)want, 1e-4f, $"{what}: Resolve in place {r}");
                    maxResolve = Math.Max(maxResolve, Math.Abs(r.Position.Z - want));

                    // A short move ending here from 5 cm away: when accepted, it ends on the reference's ground
                    // measured from the feet it started with.
                    float heading = (float)(random.NextDouble() * 2 * Math.PI);
                    var from = new Vector3(p.X - (0.05f * MathF.Cos(heading)), p.Y - (0.05f * MathF.Sin(heading)), p.Z);
                    ResolveResult m = engine.Resolve(from, Outdoor, p - from, step);
                    if (!m.IsRefused && ObjectKit.AtRest(floors, m.Position.X, m.Position.Y, p.Z, step, TerrainZ) is double wantEnd)
                    {
                        m.Position.Z.Should().BeApproximately((float)wantEnd, 1e-4f, $"{what}: move from {from:R} → {m}");
                        maxMove = Math.Max(maxMove, Math.Abs(m.Position.Z - wantEnd));
                        moves++;
                    }
                }
            }

            output.WriteLine($"seed {seed}: {compared} points ({onObjects} on object floors), {moves} moves; max error TryGetGround {maxGround:E2}, Resolve in place {maxResolve:E2}, moves {maxMove:E2}");
            compared.Should().BeGreaterThan(1000, $"seed {seed}: most samples are compared with the reference");
            moves.Should().BeGreaterThan(compared / 2, $"seed {seed}: most short moves are accepted and compared ({moves} of {compared})");
            onObjects.Should().BeGreaterThan(compared / 5, "the samples mostly land on object floors");
        }
    }

    // The cottage shell's outline at ground level, less its two ground-level doors (landblock-local).
    private static readonly (Vector2 A, Vector2 B)[] Outline =
    [
        (new(136.3f, 3.5f), new(142.5f, 3.5f)), (new(142.5f, 3.5f), new(142.5f, 19.5f)), (new(142.5f, 19.5f), new(136.3f, 19.5f)),
        (new(136.3f, 19.5f), new(136.3f, 17.1f)), (new(136.3f, 17.1f), new(133.5f, 17.1f)), (new(131.6f, 17.1f), new(124.5f, 17.1f)),
        (new(124.5f, 17.1f), new(124.5f, 13.9f)), (new(124.5f, 13.9f), new(122.5f, 13.9f)), (new(122.5f, 13.9f), new(122.5f, 9.7f)),
        (new(122.5f, 9.7f), new(124.5f, 9.7f)), (new(124.5f, 9.7f), new(124.5f, 6.5f)), (new(124.5f, 6.5f), new(136.3f, 6.5f)),
        (new(136.3f, 6.5f), new(136.3f, 6.1f)), (new(136.3f, 4.2f), new(136.3f, 3.5f)),
    ];

    [Theory]
    [InlineData("point", 5)]
    [InlineData("body", 6)]
    [InlineData("Player", 7)]
    public void A_mover_never_crosses_the_shell_except_through_a_door(string mover, int seed)
    {
        MovementOptions options = mover switch
        {
            "point" => MovementOptions.Literal,
            "body" => new MovementOptions { Body = MoverBody.Player },
            _ => MovementOptions.Player,
        };
        BuildingInfo shell = ObjectPlacements.Cottage();
        shell.Portals = [];
        var engine = new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], [ObjectSurface.Building(TestData.Holtburg, shell, RealObjects.GfxObjs, RealObjects.NoSetups)]);
        Vector2[] targets = [new(136.3f, 5.15f), new(132.55f, 17.1f), new(139f, 12f), new(130f, 12f), new(123.5f, 11.8f), new(139.5f, 19.5f), new(129.6f, 17.1f)];
        var random = new Random(seed);
        int crossings = 0, moves = 0, refused = 0;
        float closest = float.MaxValue;
        for (int walk = 0; walk < 40; walk++)
        {
            var at = new ResolveResult(new Vector3(118f + (float)(random.NextDouble() * 30), -1f + (float)(random.NextDouble() * 25), 94f), 0xA9B40000, true);
            if (RealObjectTests.InsideFootprint(new Vector2(at.Position.X, at.Position.Y), 0.6f))
            {
                continue;
            }

            Vector2 target = targets[random.Next(targets.Length)];
            for (int m = 0; m < 120; m++)
            {
                if (random.Next(25) == 0)
                {
                    target = targets[random.Next(targets.Length)];
                }

                var here = new Vector2(at.Position.X, at.Position.Y);
                Vector2 toward = target - here;
                float heading = MathF.Atan2(toward.Y, toward.X) + (float)((random.NextDouble() - 0.5) * 1.6);
                float length = mover == "point" ? 0.05f + (float)(random.NextDouble() * 0.6) : 0.05f + (float)(random.NextDouble() * 0.25);
                ResolveResult r = engine.Resolve(at.Position, at.CellId, new Vector3(MathF.Cos(heading) * length, MathF.Sin(heading) * length, 0f), 0.6f, options);
                var there = new Vector2(r.Position.X, r.Position.Y);
                moves++;
                refused += r.IsRefused ? 1 : 0;
                bool inside0 = RealObjectTests.InsideFootprint(here), inside1 = RealObjectTests.InsideFootprint(there);
                if (inside0 != inside1)
                {
                    bool west = CrossesAt(here, there, xLine: 136.3f, 4.2f, 6.1f);
                    bool north = CrossesAt(here, there, yLine: 17.1f, 131.6f, 133.5f);
                    (west || north).Should().BeTrue($"{mover}, walk {walk}, move {m}: {at} → {r} crossed the shell's outline outside its doors");
                    crossings++;
                }

                if (mover != "point")
                {
                    float d = (float)Outline.Min(s => ReferenceBody.Distance(new(there.X, there.Y), new(s.A.X, s.A.Y), new(s.B.X, s.B.Y)));
                    closest = MathF.Min(closest, d);
                    d.Should().BeGreaterThan(0.48f - 0.001f, $"{mover}, walk {walk}, move {m}: {at} → {r} overlaps the shell's wall");
                }

                r.Position.Z.Should().Be(94f, $"{r}");
                at = r;
            }
        }

        output.WriteLine($"{mover}: {moves} moves, {refused} refused, {crossings} crossings through doors, closest body centre to a wall {closest:R}");
        crossings.Should().BeGreaterThan(4, "the walks went in and out by the doors");
        refused.Should().BeGreaterThan(10, "the walks met the walls");
    }

    private static bool CrossesAt(Vector2 p0, Vector2 p1, float xLine, float min, float max)
    {
        if ((p0.X - xLine) * (p1.X - xLine) > 0f || p0.X == p1.X)
        {
            return false;
        }

        float t = (xLine - p0.X) / (p1.X - p0.X), y = p0.Y + ((p1.Y - p0.Y) * t);
        return y >= min && y <= max;
    }

    private static bool CrossesAt(Vector2 p0, Vector2 p1, float yLine, float min, float max, bool _ = true) =>
        CrossesAt(new Vector2(p0.Y, p0.X), new Vector2(p1.Y, p1.X), yLine, min, max);
}
