using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// A body that starts overlapping a wall (spawned, teleported, or put there by a rounding) is never wedged: placed
/// at random in the real Holtburg cells (and on both cellar stairs) with its centre 0.5 mm to 0.4 m inside a wall of its band (and no second wall
/// within reach), it moves away from the wall and along it where its cell's floor goes on, and no move takes it deeper
/// into any wall than it was.
/// Both world frames, the player's body at 1.2 m and 1.835 m.
/// </summary>
public class OverlapStartTests(ITestOutputHelper output)
{
    public static TheoryData<string, float> Cases() => new() { { "centred", 1.2f }, { "centred", 1.835f }, { "global", 1.2f }, { "global", 1.835f } };

    [Theory]
    [MemberData(nameof(Cases))]
    public void A_body_overlapping_a_wall_moves_along_and_away_and_never_deeper(string frame, float height)
    {
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        var gfxObjs = new Dictionary<uint, GfxObj>(RealObjects.GfxObjs);
        var withStairs = new List<EnvCell>();
        foreach ((uint stairCell, GfxObj stair, Stab placement) in ObjectPlacements.CellarStairs())
        {
            gfxObjs.Add(stair.Id, stair);
            withStairs.Add(new EnvCell { Id = stairCell, StaticObjects = [placement] });
        }

        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(), ObjectSurface.FromLandblock(TestData.Holtburg, null, withStairs, gfxObjs, RealObjects.NoSetups));
        var reference = ReferenceBody.FromCells(HoltburgCells.Fixtures.Values.Select(f => (f.EnvCell, f.CellStruct)));
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        var body = new MoverBody(0.48f, height);
        var options = new MovementOptions { Body = body, StepDownHeight = 1.5f, SweepStepLength = 0.48f };
        var random = new Random(height > 1.5f ? 31 : 29);
        uint[] cells = [.. HoltburgCells.Fixtures.Keys.Order()];
        List<ObjectSurface> stairs = ObjectSurface.FromLandblock(TestData.Holtburg, null, withStairs, gfxObjs, RealObjects.NoSetups);
        int placed = 0, away = 0, along = 0;
        double worstDeeper = 0;
        for (int attempt = 0; attempt < 20_000 && placed < 400; attempt++)
        {
            // A floor point of a random cell, then pushed toward its nearest wall edge until it overlaps it.
            uint cellId = cells[random.Next(cells.Length)];
            CellSurface cell = HoltburgCells.Surface(cellId);
            FloorTriangleInfo[] floors = [.. cell.GetFloorTriangles(), .. stairs.Where(o => o.CellId == cellId).SelectMany(o => o.GetFloorTriangles())];
            if (floors.Length == 0)
            {
                continue;
            }

            FloorTriangleInfo t = floors[random.Next(floors.Length)];
            double u = random.NextDouble(), v = random.NextDouble() * (1 - u);
            Vector3 p = t.A + ((t.B - t.A) * (float)u) + ((t.C - t.A) * (float)v);
            ResolveResult settled = engine.Resolve(origin + p, cellId, Vector3.Zero, 0.6f, options);
            if (!settled.IsOnGround || settled.CellId != cellId)
            {
                continue;
            }

            Vector3 local = settled.Position - origin;
            double zLow = local.Z + 0.6, zHigh = local.Z + height;
            List<(ReferenceBody.Vec2 A, ReferenceBody.Vec2 B)> edges = reference.Edges(zLow, zHigh);
            var c = new ReferenceBody.Vec2(local.X, local.Y);
            var near = edges.Select(e => (e, d: ReferenceBody.Distance(c, e.A, e.B))).OrderBy(x => x.d).Take(2).ToArray();
            if (near.Length == 0 || near[0].d > 1.5)
            {
                continue;
            }

            // Move the centre toward the nearest edge to a depth of 0.5 mm .. 0.4 m inside the radius.
            ReferenceBody.Vec2 closest = ReferenceBody.Closest(c, near[0].e.A, near[0].e.B);
            ReferenceBody.Vec2 outward = (c - closest) / Math.Max((c - closest).Length, 1e-9);
            double depth = 0.0005 + (random.NextDouble() * 0.4);
            ReferenceBody.Vec2 start = closest + (outward * (0.48 - depth));
            var startWorld = origin + new Vector3((float)start.X, (float)start.Y, local.Z);
            var startLocal = new ReferenceBody.Vec2((double)startWorld.X - origin.X, (double)startWorld.Y - origin.Y);
            double first = reference.Clearance(startLocal, zLow, zHigh), second = edges.Where(e => e != near[0].e).Select(e => ReferenceBody.Distance(startLocal, e.A, e.B)).DefaultIfEmpty(double.PositiveInfinity).Min();
            ResolveResult here = engine.Resolve(startWorld, cellId, Vector3.Zero, 0.6f, options);
            if (second < 0.48 + 0.3 || here.CellId != cellId || !here.IsOnGround || here.Position.Z != startWorld.Z || first > 0.48)
            {
                continue; // a second wall within reach, or a start off this cell's floor: not a single overlap
            }

            placed++;
            var tangent = new ReferenceBody.Vec2(-outward.Y, outward.X);
            foreach ((ReferenceBody.Vec2 dir, string kind) in new[] { (outward, "away"), (tangent, "along"), (tangent * -1, "along back"), ((outward + tangent) / Math.Sqrt(2), "away at 45°"), (outward * -1, "into") })
            {
                var delta = new Vector3((float)(dir.X * 0.1), (float)(dir.Y * 0.1), 0f);
                bool floorAhead = engine.TryGetGround(here.Position + delta, cellId, 0.6f, out float ahead, out _, out _) && MathF.Abs(ahead - local.Z) <= 0.6f;
                string what = $"{frame}, height {height}: 0x{cellId:X8} at {startLocal} ({first:F4} m from the wall, {second:F3} from the next) by {delta} ({kind})";
                ResolveResult r = engine.Resolve(here.Position, here.CellId, delta, 0.6f, options);
                var end = new ReferenceBody.Vec2((double)r.Position.X - origin.X, (double)r.Position.Y - origin.Y);
                double after = reference.Clearance(end, r.Position.Z - origin.Z + 0.6, r.Position.Z - origin.Z + height);
                double deeper = Math.Min(first, 0.48) - after;
                worstDeeper = Math.Max(worstDeeper, deeper);
                deeper.Should().BeLessThan(1e-4, $"never deeper into a wall: {what} → {r} (clearance {after:F5})");
                if ((kind.StartsWith("away") || kind.StartsWith("along")) && floorAhead)
                {
                    r.Outcome.Should().NotBe(ResolveOutcome.Wall, $"not wedged: {what} → {r}");
                    (end - startLocal).Length.Should().BeGreaterThan(0.05, $"it moves: {what} → {r}");
                    away += kind.StartsWith("away") ? 1 : 0;
                    along += kind.StartsWith("along") ? 1 : 0;
                }
            }
        }

        output.WriteLine($"{frame}, height {height}: {placed} overlapping starts, {away} moves away and {along} along, worst extra depth {worstDeeper:E2} m");
        placed.Should().BeGreaterThan(height > 1.5f ? 100 : 5, "overlapping starts were found (a 0.6 m band has few walls to start against)");
    }
}
