using AcDream.Testing;
using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Every answer among objects on rolling terrain is a fixed point (resolving it again in place returns it
/// bit for bit) with honest ground (<c>IsOnGround</c> exactly when its Z is within the ground tolerance of
/// <see cref="PhysicsEngine.TryGetGround(Vector3, uint, float, out float, out Vector3, out uint)"/> there):
/// real buildings, stair pieces, trees and low platforms placed at random on four landblocks at the far corner of the
/// world (some reaching over the seams), seeded walks toward them of 5 cm to 4 m per move, the point, the
/// body and <see cref="MovementOptions.Player"/>, in the global frame and a frame centred far away.
/// </summary>
[Trait("Mutation", "ObjectQueries")]
public class ObjectRestInvariantTests(ITestOutputHelper output)
{
    private static readonly uint[] Landblocks = [0xFDFDFFFFu, 0xFEFDFFFFu, 0xFDFEFFFFu, 0xFEFEFFFFu];

    /// <summary>Heights in metres per table index: a quarter metre.</summary>
    private static readonly float[] Table = Enumerable.Range(0, 256).Select(i => 30f + (0.25f * i)).ToArray();

    public static TheoryData<string, string, int> Cases()
    {
        var data = new TheoryData<string, string, int>();
        foreach (string frame in new[] { "global", "centred" })
        {
            foreach (string effects in new[] { "literal", "body", "Player" })
            {
                data.Add(frame, effects, frame.Length + (effects.Length * 7));
            }
        }

        return data;
    }

    /// <summary>Rolling heights shared by every landblock along its seams (a function of the global vertex).</summary>
    private static byte[] Heights(uint landblock)
    {
        int x0 = CellIds.LandblockX(landblock) * 8, y0 = CellIds.LandblockY(landblock) * 8;
        return TestData.Heights((x, y) => 40 + (int)(12 * Math.Sin((x0 + x) * 0.9)) + (int)(10 * Math.Cos((y0 + y) * 0.7)));
    }

    /// <summary>The objects of one landblock: two buildings, stair pieces and trees at random, each standing on the terrain.</summary>
    private static List<ObjectSurface> Objects(Random random, TerrainSurface terrain)
    {
        var objects = new List<ObjectSurface>();
        (Setup tree, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree(0.4f, 6f);
        uint[] models = [ObjectPlacements.SmallBuilding, ObjectPlacements.SmallBuilding, ObjectPlacements.CottageShell, ObjectPlacements.StairPiece, ObjectPlacements.StairPiece, 0x01000ACA];
        for (int i = 0; i < 14; i++)
        {
            // Some near the seams (within 8 m of an edge), so that they reach over them.
            float x = i % 4 == 0 ? (random.Next(2) == 0 ? 2f : 186f) + (float)(random.NextDouble() * 4) : 12f + (float)(random.NextDouble() * 168);
            float y = i % 5 == 0 ? (random.Next(2) == 0 ? 2f : 186f) + (float)(random.NextDouble() * 4) : 12f + (float)(random.NextDouble() * 168);
            float z = terrain.SampleZ(x, y) + (float)((random.NextDouble() * 0.6) - 0.4);
            float yaw = (float)(random.NextDouble() * 2 * Math.PI);
            objects.Add(i < 11
                ? new ObjectSurface(RealObjects.GfxObjs[models[i % models.Length]], ObjectKit.At(new Vector3(x, y, z), yaw), 0)
                : new ObjectSurface(tree, parts, ObjectKit.At(new Vector3(x, y, z), 0f), 0));
        }

        // Low platforms a step or two above the terrain: floors alone (a walker reaches over them without
        // crossing a wall) and boxes with sides, 2 to 4 m across.
        for (int i = 0; i < 10; i++)
        {
            float x = 12f + (float)(random.NextDouble() * 168), y = 12f + (float)(random.NextDouble() * 168), half = 1f + (float)random.NextDouble();
            float top = terrain.SampleZ(x, y) + 0.2f + (float)(random.NextDouble() * 0.8);
            GfxObj platform = i % 2 == 0
                ? ObjectKit.Gfx(0x01000500u + (uint)i, TestData.Square(-half, -half, half, half, 0f))
                : ObjectKit.Gfx(0x01000500u + (uint)i,
                    TestData.Square(-half, -half, half, half, 0f),
                    TestData.Wall(-half, -half, half, -half, -2f, 0f), TestData.Wall(half, -half, half, half, -2f, 0f),
                    TestData.Wall(half, half, -half, half, -2f, 0f), TestData.Wall(-half, half, -half, -half, -2f, 0f));
            objects.Add(new ObjectSurface(platform, ObjectKit.At(new Vector3(x, y, top), (float)(random.NextDouble() * 2 * Math.PI)), 0));
        }

        return objects;
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void Answers_among_objects_on_rolling_terrain_are_fixed_points_with_honest_ground(string frame, string effects, int seed)
    {
        MovementOptions options = effects switch
        {
            "literal" => MovementOptions.Literal,
            "body" => new MovementOptions { Body = MoverBody.Player },
            _ => MovementOptions.Player,
        };
        var random = new Random(seed);
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(0x0101FFFFu);
        var targets = new List<(uint Landblock, Vector3 Local)>();
        var objectsOf = new Dictionary<uint, List<ObjectSurface>>();
        foreach (uint landblock in Landblocks)
        {
            var terrain = new TerrainSurface(Heights(landblock), Table, landblock);
            List<ObjectSurface> objects = Objects(random, terrain);
            objectsOf[landblock >> 16] = objects;
            engine.AddLandblock(landblock, terrain, [], objects);
            targets.AddRange(objects.Select(o => (landblock, (o.BoundsMin + o.BoundsMax) / 2f)));
        }

        int answers = 0, fixedChecked = 0, onObjects = 0, slid = 0, refused = 0, walls = 0;
        for (int walk = 0; walk < 40; walk++)
        {
            (uint landblock, Vector3 local) = targets[random.Next(targets.Count)];
            Vector3 origin = engine.GetLandblockOrigin(landblock);
            // A start within 8 m of it, inside the four landblocks, on the terrain there.
            Vector3 corner = engine.GetLandblockOrigin(Landblocks[0]);
            var start = origin + new Vector3(local.X + (float)((random.NextDouble() * 16) - 8), local.Y + (float)((random.NextDouble() * 16) - 8), 0f);
            start = Vector3.Clamp(start, corner + new Vector3(1f, 1f, 0f), corner + new Vector3(383f, 383f, 0f));
            uint startCell = engine.LandblockAt(start) & 0xFFFF0000;
            engine.TryGetGround(start, startCell, out float terrainZ, out _).Should().BeTrue();
            ResolveResult at = engine.Resolve(start with { Z = terrainZ }, startCell, Vector3.Zero, 0.6f, options);
            Vector3 target = origin + local;
            for (int m = 0; m < 40; m++)
            {
                Vector2 toward = new Vector2(target.X - at.Position.X, target.Y - at.Position.Y);
                float heading = MathF.Atan2(toward.Y, toward.X) + (float)((random.NextDouble() - 0.5) * 1.5);
                float length = 0.05f + (float)(random.NextDouble() * (random.Next(6) == 0 ? 4 : 0.6));
                var delta = new Vector3(MathF.Cos(heading) * length, MathF.Sin(heading) * length, 0f);
                string what = $"{frame}, {effects}, walk {walk}, move {m}: {at.Position:R} in 0x{at.CellId:X8} by {delta:R}";
                ResolveResult r = engine.Resolve(at.Position, at.CellId, delta, 0.6f, options);
                float.IsFinite(r.Position.X + r.Position.Y + r.Position.Z).Should().BeTrue(what);
                answers++;
                slid += r.Outcome == ResolveOutcome.Slid ? 1 : 0;
                refused += r.IsRefused ? 1 : 0;

                bool found = engine.TryGetGround(r.Position, r.CellId, 0.6f, out float ground, out _, out uint objectId);
                if (r.Outcome == ResolveOutcome.Held)
                {
                    break; // walked off the four landblocks: held at their edge, on ground it does not know
                }

                bool onPoint = found && MathF.Abs(r.Position.Z - ground) <= PhysicsConstants.GroundTolerance;
                Vector3 lbOrigin = engine.GetLandblockOrigin(r.CellId);
                bool held = !onPoint && FootingReference.HoldsAnswer(options, [], objectsOf[r.CellId >> 16], r, new Vector2(r.Position.X - lbOrigin.X, r.Position.Y - lbOrigin.Y));
                bool stands = onPoint || held;
                objectId = held ? uint.MaxValue : objectId; // held by an object's floor under its footprint: any object's

                r.IsOnGround.Should().Be(stands, $"honest ground: {what} → {r}; ground {(found ? ground.ToString("R") : "none")} (object 0x{objectId:X8})");

                // What the move met: the same answer, the floor it stands on, and every wall stop named.
                ResolveResult reported = engine.Resolve(at.Position, at.CellId, delta, 0.6f, options, out MoveReport report);
                reported.Should().Be(r, $"the answer with the report: {what}");
                report.Floor.Kind.Should().BeOneOf(
                    !r.IsOnGround ? [SurfaceKind.None] : objectId == uint.MaxValue ? [SurfaceKind.ObjectFloor, SurfaceKind.Terrain] : objectId != 0 ? [SurfaceKind.ObjectFloor] : [SurfaceKind.Terrain],
                    $"floor (held by footing: an object's floor under its footprint, or the terrain where that lies at the same height): {what} → {r}; {report}");
                if (objectId != uint.MaxValue)
                {
                    report.Floor.Id.Should().Be(!r.IsOnGround ? 0u : objectId != 0 ? objectId : r.CellId, $"floor id: {what} → {r}; {report}");
                }

                bool walled = r.Outcome is ResolveOutcome.Wall or ResolveOutcome.OuterWall or ResolveOutcome.Edge || (r.Outcome == ResolveOutcome.Slid && r.SurfaceNormal.Z == 0f);
                report.Wall.Kind.Should().BeOneOf(walled ? [SurfaceKind.ObjectWall, SurfaceKind.BuildingShell, SurfaceKind.Cylinder, SurfaceKind.FloorEdge] : [SurfaceKind.None], $"wall: {what} → {r}; {report}");
                report.Wall.Normal.Should().Be(walled ? r.SurfaceNormal : Vector3.Zero, $"wall normal: {what} → {r}; {report}");
                walls += walled ? 1 : 0;
                onObjects += stands && objectId != 0 ? 1 : 0;
                if (r.IsOnGround)
                {
                    ResolveResult again = engine.Resolve(r.Position, r.CellId, Vector3.Zero, 0.6f, options);
                    (again.Position, again.CellId, again.IsOnGround).Should().Be((r.Position, r.CellId, r.IsOnGround), $"fixed point: {what} → {r}; in place → {again}");
                    fixedChecked++;
                }

                at = r.IsOnGround ? r : r with { Position = r.Position with { Z = found ? ground : r.Position.Z } };
            }
        }

        output.WriteLine($"{frame}, {effects}: {answers} answers ({fixedChecked} re-resolved in place), {onObjects} on object floors, {slid} slid, {refused} refused, {walls} wall stops or slides named");
        fixedChecked.Should().BeGreaterThan(answers / 2, "most answers stand on the ground and are re-resolved");
        onObjects.Should().BeGreaterThan(50, "the walks climbed onto object floors");
        if (effects != "literal")
        {
            slid.Should().BeGreaterThan(20, "the bodies slid along the objects' walls");
        }
    }
}
