using AcDream.Testing;
using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// The answers' invariants among objects, in both world frames (fixed point, honest ground, no NaN);
/// and "off means free": an empty object list answers bit for bit as the three-argument AddLandblock,
/// and so do objects in a landblock far from the moves.
/// </summary>
[Trait("Mutation", "ObjectQueries")]
public class ObjectInvariantTests(ITestOutputHelper output)
{
    private const uint Holtburg = TestData.Holtburg;
    private const uint East = 0xAAB4FFFF;

    /// <summary>A landblock three north of Holtburg, beyond every move's reach.</summary>
    private const uint Far = 0xA9B7FFFF;

    /// <summary>Holtburg's cells with its two buildings, a staircase, a stair end piece and three trees outdoors.</summary>
    private static List<ObjectSurface> Objects() => [.. RealObjects.HoltburgBuildings(), .. OutdoorObjects()];

    /// <summary>The staircase, the stair end piece and the three trees (landblock-local, outdoors).</summary>
    private static List<ObjectSurface> OutdoorObjects()
    {
        var objects = new List<ObjectSurface>();
        for (int k = 0; k < 6; k++)
        {
            objects.Add(new ObjectSurface(RealObjects.GfxObjs[ObjectPlacements.StairPiece], ObjectKit.At(new Vector3(110f + (0.5f * k), 30f, 94.2f + (0.4f * k)), 0f), 0));
        }

        objects.Add(new ObjectSurface(RealObjects.GfxObjs[0x01000ACA], ObjectKit.At(new Vector3(118f, 35f, 94f), 2.1f), 0));
        (Setup tree, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree();
        foreach (Vector2 at in new Vector2[] { new(120f, 25f), new(126f, 24f), new(145f, 10f) })
        {
            objects.Add(new ObjectSurface(tree, parts, ObjectKit.At(new Vector3(at, 94f), 0f), 0));
        }

        return objects;
    }

    public static TheoryData<string, string> Cases() => new()
    {
        { "global", "literal" }, { "global", "step down" }, { "global", "Player" }, { "global", "body" },
        { "centred", "literal" }, { "centred", "step down" }, { "centred", "Player" }, { "centred", "body" },
    };

    private static MovementOptions Options(string name) => name switch
    {
        "literal" => MovementOptions.Literal,
        "step down" => new MovementOptions { StepDownHeight = 0.75f, SweepStepLength = 0.48f },
        "Player" => MovementOptions.Player,
        _ => new MovementOptions { Body = MoverBody.Player },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void Answers_among_objects_are_fixed_points_with_honest_ground_and_no_NaN(string frame, string effects)
    {
        MovementOptions options = Options(effects);
        var engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        List<CellSurface> cells = HoltburgCells.Surfaces();
        List<ObjectSurface> objects = Objects();
        engine.AddLandblock(Holtburg, TestData.FlatTerrain(94f), cells, objects);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        var random = new Random(frame.Length + effects.Length);
        Vector2[] targets = [new(136.3f, 5.15f), new(139f, 12f), new(112f, 30f), new(113f, 30.5f), new(118f, 35f), new(120f, 25f), new(158f, 37f), new(155f, 31f), new(160f, 40f), new(132.5f, 17.1f)];
        int answers = 0, onObjects = 0, airborne = 0, indoors = 0;
        for (int walk = 0; walk < 50; walk++)
        {
            // Every third walk climbs the staircase (x 109.75…112.75 at y 30) or the small building's ramp, gently.
            bool climb = walk % 3 == 0;
            Vector2 start = climb
                ? (walk % 2 == 0 ? new Vector2(108.5f, 30f + (float)((random.NextDouble() * 1) - 0.5)) : new Vector2(151.5f, 35.5f))
                : targets[random.Next(targets.Length)] + new Vector2((float)((random.NextDouble() * 10) - 5), (float)((random.NextDouble() * 10) - 5));
            var at = new ResolveResult(origin + new Vector3(start, 94f + (float)(random.NextDouble() * 0.5)), 0xA9B40000, true);
            float step = 0.3f + (float)(random.NextDouble() * 0.7);
            Vector2 target = climb ? (walk % 2 == 0 ? new Vector2(114f, 30f) : new Vector2(158f, 37f)) : targets[random.Next(targets.Length)];
            for (int m = 0; m < 50; m++)
            {
                Vector2 toward = target - new Vector2(at.Position.X - origin.X, at.Position.Y - origin.Y);
                float heading = MathF.Atan2(toward.Y, toward.X) + (float)((random.NextDouble() - 0.5) * (climb ? 0.6 : 2));
                float length = (float)(random.NextDouble() * (climb ? 0.3 : random.Next(10) == 0 ? 4 : 0.5));
                var delta = new Vector3(MathF.Cos(heading) * length, MathF.Sin(heading) * length, 0f);
                string what = $"{frame}, {effects}, walk {walk}, move {m}: {at.Position:R} in 0x{at.CellId:X8} by {delta:R}, step {step:R}";
                ResolveResult r = engine.Resolve(at.Position, at.CellId, delta, step, options);
                (float.IsNaN(r.Position.X) || float.IsNaN(r.Position.Y) || float.IsNaN(r.Position.Z) || float.IsNaN(r.SurfaceNormal.X)).Should().BeFalse($"{what} → {r}");
                answers++;

                bool found = engine.TryGetGround(r.Position, r.CellId, step, out float ground, out _, out uint objectId);
                bool stands = (found && MathF.Abs(r.Position.Z - ground) <= PhysicsConstants.GroundTolerance)
                    || FootingReference.HoldsAnswer(options, cells, objects, r, new Vector2(r.Position.X - origin.X, r.Position.Y - origin.Y));
                if (r.Outcome != ResolveOutcome.Held)
                {
                    r.IsOnGround.Should().Be(stands, $"honest ground: {what} → {r}; ground {(found ? ground.ToString("R") : "none")} (object 0x{objectId:X8})");
                }

                onObjects += stands && objectId != 0 ? 1 : 0;
                airborne += r.IsOnGround ? 0 : 1;
                indoors += CellIds.IsIndoor(r.CellId) ? 1 : 0;
                if (r.IsOnGround || options.StepDownHeight is not null)
                {
                    ResolveResult again = engine.Resolve(r.Position, r.CellId, Vector3.Zero, step, options);
                    (again.Position, again.CellId, again.IsOnGround).Should().Be((r.Position, r.CellId, r.IsOnGround), $"fixed point: {what} → {r}; in place → {again}");
                }

                at = r.IsOnGround ? r : r with { Position = r.Position with { Z = found ? ground : r.Position.Z } };
                if (!climb && random.Next(15) == 0)
                {
                    target = targets[random.Next(targets.Length)];
                }
            }
        }

        output.WriteLine($"{frame}, {effects}: {answers} answers, {onObjects} on object floors, {airborne} airborne, {indoors} indoors");
        onObjects.Should().BeGreaterThan(100, "the walks stood on object floors");
        indoors.Should().BeGreaterThan(0, "the walks went indoors");
    }

    public static TheoryData<string> Movers() => ["literal", "Player", "body"];

    [Theory]
    [MemberData(nameof(Movers))]
    public void An_empty_object_list_answers_bit_for_bit_as_the_three_argument_call(string effects)
    {
        MovementOptions options = Options(effects);
        var random = new Random(effects.Length * 7);
        var terrain = new TerrainSurface(TestData.RandomHeights(random), TestData.NonLinearTable(), East);
        var flat = TestData.FlatTerrain(94f);
        var without = new PhysicsEngine(Holtburg);
        var empty = new PhysicsEngine(Holtburg);
        without.AddLandblock(Holtburg, flat, HoltburgCells.Surfaces());
        without.AddLandblock(East, terrain, []);
        empty.AddLandblock(Holtburg, flat, HoltburgCells.Surfaces(), []);
        empty.AddLandblock(East, terrain, [], []);

        // The three-argument call forwards an empty list, so without and empty share one path; the check
        // with teeth is an engine that also holds objects, registered first, in a landblock far from every
        // move: the staircase, the stair end piece and a tree every 6 m over the whole landblock, at the
        // moves' landblock-local coordinates.
        (Setup tree, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree();
        List<ObjectSurface> forest = OutdoorObjects();
        for (int i = 0; i < 32; i++)
        {
            for (int j = 0; j < 32; j++)
            {
                forest.Add(new ObjectSurface(tree, parts, ObjectKit.At(new Vector3(3f + (6f * i), 3f + (6f * j), 94f), 0f), 0));
            }
        }

        var elsewhere = new PhysicsEngine(Holtburg);
        elsewhere.AddLandblock(Far, TestData.FlatTerrain(94f, Far), [], forest);
        elsewhere.AddLandblock(Holtburg, flat, HoltburgCells.Surfaces(), []);
        elsewhere.AddLandblock(East, terrain, [], []);
        List<CellSurface> cells = HoltburgCells.Surfaces();
        int moves = 0, indoors = 0, differentCell = 0;
        for (int walk = 0; walk < 120; walk++)
        {
            ResolveResult at;
            if (walk % 2 == 0)
            {
                CellSurface cell = cells[random.Next(cells.Count)];
                var p = new Vector2(cell.Origin.X, cell.Origin.Y) + new Vector2((float)((random.NextDouble() * 3) - 1.5), (float)((random.NextDouble() * 3) - 1.5));
                if (cell.SampleFloorZ(p.X, p.Y, cell.Origin.Z) is not float z)
                {
                    continue;
                }

                at = new ResolveResult(new Vector3(p, z), cell.CellId, true);
            }
            else
            {
                var p = new Vector2(100f + (float)(random.NextDouble() * 180), (float)(random.NextDouble() * 190));
                at = new ResolveResult(new Vector3(p, 94f), 0xA9B40000, true);
            }

            float step = 0.3f + (float)(random.NextDouble() * 0.7);
            for (int m = 0; m < 30; m++)
            {
                var delta = new Vector3((float)((random.NextDouble() - 0.5) * 1.2), (float)((random.NextDouble() - 0.5) * 1.2), 0f) * (random.Next(12) == 0 ? 8 : 1);
                ResolveResult a = without.Resolve(at.Position, at.CellId, delta, step, options);
                ResolveResult b = empty.Resolve(at.Position, at.CellId, delta, step, options);
                ResolveResult c = elsewhere.Resolve(at.Position, at.CellId, delta, step, options);
                string what = $"{effects}, walk {walk}, move {m}: {at} by {delta:R}, step {step:R}";
                b.Should().Be(a, what);
                b.Position.Should().Be(a.Position, what);
                b.SurfaceNormal.Should().Be(a.SurfaceNormal, what);
                c.Should().Be(a, $"objects in a landblock far away: {what}");
                without.TryGetGround(a.Position, a.CellId, step, out float za, out Vector3 na, out uint oa).Should().Be(empty.TryGetGround(a.Position, a.CellId, step, out float zb, out Vector3 nb, out uint ob), $"ground under {a}: {what}");
                (za, na, oa).Should().Be((zb, nb, ob), $"ground under {a}: {what}");
                elsewhere.TryGetGround(a.Position, a.CellId, step, out float zc, out Vector3 nc, out uint oc);
                (zc, nc, oc).Should().Be((za, na, oa), $"ground under {a}, objects in a landblock far away: {what}");
                moves++;
                indoors += CellIds.IsIndoor(a.CellId) ? 1 : 0;
                differentCell += a.CellId != at.CellId ? 1 : 0;
                at = a;
            }
        }

        output.WriteLine($"{effects}: {moves} moves, {indoors} indoors, {differentCell} changed cell");
        moves.Should().BeGreaterThan(2000);
        indoors.Should().BeGreaterThan(200);
    }
}
