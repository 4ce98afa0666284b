using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Api;

/// <summary>Issue 9: the engine says why a move stopped (outcome and normal), and the host's helpers; the object queries and the surfaces seen by callers.</summary>
[Trait("Mutation", "PortalTraversal")]
public class OutcomeAndHostApiTests
{
    private const float Step = 0.5f;

    /// <summary>Terrain rising 100 m per 24 m east of x = 48 (table i = i m); flat 0 m west of it.</summary>
    private static PhysicsEngine Cliff()
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, new TerrainSurface(Heights((x, _) => x >= 3 ? 100 : 0), Enumerable.Range(0, 256).Select(i => (float)i).ToArray(), Holtburg), []);
        return engine;
    }

    [Fact]
    public void Resolve_EachKindOfStop_ReportsItsOutcomeAndNormal()
    {
        PhysicsEngine cliff = Cliff();
        ResolveResult step = cliff.Resolve(new Vector3(47.9f, 96, 0), 0, new Vector3(0.5f, 0, 0), Step);
        step.Outcome.Should().Be(ResolveOutcome.StepTooHigh, $"{step}");
        step.IsRefused.Should().BeTrue();
        Vector3 slopeNormal = Vector3.Normalize(new Vector3(-100f / 24f, 0, 1));
        Vector3.Distance(step.SurfaceNormal, slopeNormal).Should().BeLessThan(1e-5f, $"the slope's unit normal, facing the mover: {step.SurfaceNormal}");

        // Walkable slope: a gentle rise climbed by a small step is refused as too steep, not as a step.
        ResolveResult steep = cliff.Resolve(new Vector3(48.2f, 96, 100f * 0.2f / 24f), 0, new Vector3(0.1f, 0, 0), 2f, new MovementOptions { WalkableSlope = true });
        steep.Outcome.Should().Be(ResolveOutcome.SlopeTooSteep, $"{steep}");
        Vector3.Distance(steep.SurfaceNormal, slopeNormal).Should().BeLessThan(1e-5f, $"{steep.SurfaceNormal}");

        ResolveResult moved = cliff.Resolve(new Vector3(20, 96, 0), 0, new Vector3(0.5f, 0, 0), Step);
        (moved.Outcome, moved.SurfaceNormal, moved.IsRefused).Should().Be((ResolveOutcome.Moved, Vector3.Zero, false), $"{moved}");

        ResolveResult unloaded = cliff.Resolve(new Vector3(191.8f, 96, 0), 0, new Vector3(0.5f, 0, 0), Step);
        unloaded.Outcome.Should().Be(ResolveOutcome.UnloadedAhead, $"{unloaded}");
        unloaded.SurfaceNormal.Should().Be(Vector3.Zero);

        var edge = new PhysicsEngine();
        edge.AddLandblock(0xFE10FFFFu, FlatTerrain(5f, 0xFE10FFFFu), []);
        Vector3 origin = edge.GetLandblockOrigin(0xFE10FFFFu);
        edge.Resolve(origin + new Vector3(191.8f, 50, 5), 0xFE100001u, new Vector3(0.5f, 0, 0), Step).Outcome
            .Should().Be(ResolveOutcome.EdgeOfWorld, "east of landblock X 0xFE is off the world");

        cliff.RemoveLandblock(Holtburg);
        cliff.Resolve(new Vector3(20, 96, 0), 0, new Vector3(0.5f, 0, 0), Step).Outcome.Should().Be(ResolveOutcome.Held);
    }

    [Fact]
    public void Resolve_IndoorWallBesideADoorway_ReportsTheWallFacingTheMover()
    {
        // Room x 10..14 with a doorway in its east wall (x = 14, y 11.5..12.5) to the outdoors.
        CellSurface room = new CellBuilder(0xA9B40100u).Floor(10, 10, 14, 14, 0)
            .Portal(0xFFFF, new Vector3(12, 12, 1), Wall(14, 11.5f, 14, 12.5f, 0, 2)).Build();
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(0f), [room]);

        ResolveResult wall = engine.Resolve(new Vector3(13.9f, 10.5f, 0), 0xA9B40100u, new Vector3(0.2f, 0, 0), Step);
        wall.Outcome.Should().Be(ResolveOutcome.Wall, $"{wall}");
        Vector3.Distance(wall.SurfaceNormal, new Vector3(-1, 0, 0)).Should().BeLessThan(1e-5f, $"the wall at x = 14 faces west, into the room: {wall.SurfaceNormal}");

        ResolveResult noPortal = engine.Resolve(new Vector3(10.1f, 12f, 0), 0xA9B40100u, new Vector3(-0.2f, 0, 0), Step);
        (noPortal.Outcome, noPortal.SurfaceNormal).Should().Be((ResolveOutcome.Wall, Vector3.Zero), "no floor and no portal: a wall the engine has no polygon for");

        ResolveResult outer = engine.Resolve(new Vector3(12f, 8f, 0), 0, new Vector3(0, 2.5f, 0), Step, new MovementOptions { DoorsOnly = true });
        outer.Outcome.Should().Be(ResolveOutcome.OuterWall, $"{outer}");
    }

    [Fact]
    public void Resolve_SweptMoveStoppedPartWay_ReportsTheRefusalAtTheLastAcceptedSubStep()
    {
        PhysicsEngine cliff = Cliff();
        ResolveResult r = cliff.Resolve(new Vector3(45f, 96, 0), 0, new Vector3(5f, 0, 0), Step, new MovementOptions { SweepStepLength = 0.5f });
        r.Outcome.Should().Be(ResolveOutcome.StepTooHigh, $"{r}");
        r.Position.X.Should().BeInRange(47.4f, 48f, "the last sub-step before the cliff");
        r.IsOnGround.Should().BeTrue();
    }

    [Fact]
    public void HostHelpers_IdsFramesAndGround_AgreeWithTheEngine()
    {
        CellIds.LandblockOf(0xA9B40143u).Should().Be(0xA9B4FFFFu);
        (CellIds.LandblockX(0xA9B40143u), CellIds.LandblockY(0xA9B40143u), CellIds.CellNumber(0xA9B40143u)).Should().Be((0xA9, 0xB4, (ushort)0x0143));
        CellIds.Landblock(0xA9, 0xB4).Should().Be(0xA9B4FFFFu);
        (CellIds.IsIndoor(0xA9B40143u), CellIds.IsOutdoor(0xA9B40143u)).Should().Be((true, false));
        (CellIds.IsIndoor(0xA9B40040u), CellIds.IsOutdoor(0xA9B40040u), CellIds.IsOutdoor(0xA9B40041u)).Should().Be((false, true, false));
        CellIds.OutdoorCellNumber(24f, 0f).Should().Be(0x0009u);
        CellIds.OutdoorCellNumber(191.99f, 191.99f).Should().Be(0x0040u);
        var terrain = new TerrainSurface(Heights((x, y) => (x * 3) + y), NonLinearTable(), Holtburg);
        for (float x = 0; x <= 192; x += 0.75f)
        {
            CellIds.OutdoorCellNumber(x, 191 - x).Should().Be(terrain.ComputeOutdoorCellId(x, 191 - x), $"one formula, at ({x}, {191 - x})");
        }

        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, terrain, [new CellBuilder(0xA9B40100u, new Vector3(50, 50, 10)).Floor(-2, -2, 2, 2, 0).Build()]);
        engine.LandblockAt(new Vector3(-0.5f, 5, 0)).Should().Be(0xA8B4FFFFu);
        engine.LandblockAt(new Vector3(1e12f, -1e12f, 0)).Should().Be(0xFE00FFFFu, "off the world clamps to its nearest edge");
        engine.ToWorld(0xA9B50001u, new Vector3(1, 2, 3)).Should().Be(new Vector3(1, 194, 3));
        engine.ToLandblockLocal(0xA9B50001u, new Vector3(1, 194, 3)).Should().Be(new Vector3(1, 2, 3));

        engine.TryGetGround(new Vector3(30, 40, 0), 0, out float z, out Vector3 normal).Should().BeTrue();
        z.Should().Be(terrain.SampleZ(30, 40));
        normal.Z.Should().BeInRange(0.5f, 1f);
        ResolveResult standing = engine.Resolve(new Vector3(30, 40, 99), 0, Vector3.Zero, 500f);
        standing.Position.Z.Should().Be(z, "the ground a zero move stands on");

        engine.TryGetGround(new Vector3(50.5f, 50.5f, 12), 0xA9B40100u, out float floor, out Vector3 up).Should().BeTrue();
        (floor, up).Should().Be((10f, Vector3.UnitZ));
        engine.TryGetGround(new Vector3(60, 60, 12), 0xA9B40100u, out _, out _).Should().BeFalse("no floor of the cell there");
        engine.TryGetGround(new Vector3(300, 60, 12), 0, out _, out _).Should().BeFalse("landblock 0xAAB4 is not loaded");
    }

    [Fact]
    public void GetFloorTriangles_AreTheFloorsTheEngineSamples()
    {
        foreach (CellSurface cell in HoltburgCells.Surfaces())
        {
            foreach (FloorTriangleInfo t in cell.GetFloorTriangles())
            {
                Vector3 centre = (t.A + t.B + t.C) / 3f;
                float? z = cell.SampleFloorZ(centre.X, centre.Y, centre.Z);
                z.Should().NotBeNull($"0x{cell.CellId:X8}: the centre of {t} is on a floor");
                z!.Value.Should().BeApproximately(centre.Z, 1e-4f, $"0x{cell.CellId:X8}: {t}");
            }
        }
    }

    [Fact]
    public void The_cottage_shells_floors_and_walls_are_its_polygons()
    {
        ObjectSurface shell = RealObjects.HoltburgBuildings()[0];
        shell.ObjectId.Should().Be(ObjectPlacements.CottageShell);
        shell.IsBuilding.Should().BeTrue();
        shell.DoorCellIds.Should().Equal(0xA9B40145, 0xA9B4014C, 0xA9B4014E, 0xA9B4014F);
        List<RefFloor> polygons = ObjectKit.Floors(RealObjects.GfxObjs[ObjectPlacements.CottageShell], ObjectPlacements.Cottage().Frame);
        polygons.Should().HaveCount(74);
        shell.GetWalls().Should().HaveCount(69, "74 physics polygons less the 5 walkable ones");
        FloorTriangleInfo[] triangles = shell.GetFloorTriangles();
        double area = triangles.Sum(t => Math.Abs(Vector3.Cross(t.B - t.A, t.C - t.A).Z) / 2);
        double expected = polygons.Where(p => p.Walkable).Sum(p => Math.Abs(AreaXY(p)));
        area.Should().BeApproximately(expected, 1e-3, "the floor triangles cover exactly the walkable polygons (roof top z 102, chimney top z 104)");
        triangles.Select(t => MathF.Round(t.A.Z, 3)).Distinct().Should().BeEquivalentTo(new[] { 102f, 104f });
        shell.BoundsMin.X.Should().BeApproximately(122.5f, 1e-3f);
        shell.BoundsMax.X.Should().BeApproximately(142.5f, 1e-3f);
        shell.BoundsMin.Y.Should().BeApproximately(3.5f, 1e-3f);
        shell.BoundsMax.Y.Should().BeApproximately(19.5f, 1e-3f);
        shell.BoundsMin.Z.Should().BeApproximately(94f, 1e-3f);
        shell.BoundsMax.Z.Should().BeApproximately(104f, 1e-3f);
    }

    private static double AreaXY(RefFloor p)
    {
        double a = 0;
        for (int i = 0; i < p.V.Length; i++)
        {
            var u = p.V[i];
            var v = p.V[(i + 1) % p.V.Length];
            a += (u.X * v.Y) - (v.X * u.Y);
        }

        return a / 2;
    }
}
