using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

[Trait("Mutation", "PortalTraversal")]
public class PhysicsEngineTests
{
    private const float Step = 0.5f;

    /// <summary>An engine centred on Holtburg (world = 0xA9B4-local) with these landblocks registered.</summary>
    private static PhysicsEngine MakeEngine(TerrainSurface terrain, params CellSurface[] cells)
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, terrain, cells);
        return engine;
    }

    [Fact]
    public void Resolve_WalkOnFlatTerrain_ZIsTerrain()
    {
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f));

        ResolveResult r = engine.Resolve(new Vector3(100, 100, 50), 0xA9B40000u, new Vector3(1, 0, 0), Step);

        r.Position.Should().Be(new Vector3(101, 100, 50));
        r.IsOnGround.Should().BeTrue();
        r.CellId.Should().Be(0xA9B40025u, "(101, 100) is outdoor cell cx 4, cy 4: 4 * 8 + 4 + 1 = 0x25");
    }

    [Fact]
    public void Resolve_WalkUpAHill_ZFollowsTheSlope()
    {
        // Z rises from 50 m at x = 0 to 60 m at x = 24 (vertex column 1) and stays 60 beyond.
        float[] table = ConstantTable(0f);
        table[1] = 50f;
        table[2] = 60f;
        PhysicsEngine engine = MakeEngine(new TerrainSurface(Heights((x, _) => x == 0 ? 1 : 2), table, Holtburg));

        var pos = new Vector3(0, 30, 50);
        uint cell = 0xA9B40000u;
        for (int i = 0; i < 48; i++)
        {
            ResolveResult r = engine.Resolve(pos, cell, new Vector3(0.5f, 0, 0), Step);
            float expected = 50f + (10f * MathF.Min(r.Position.X, 24f) / 24f);
            r.Position.X.Should().BeApproximately(pos.X + 0.5f, 1e-4f, $"step {i} climbs (rise 0.21 m ≤ {Step} m)");
            r.Position.Z.Should().BeApproximately(expected, 1e-4f, $"step {i} at x {r.Position.X}");
            (pos, cell) = (r.Position, r.CellId);
        }

        pos.Z.Should().Be(60f);
    }

    [Fact]
    public void Resolve_StepUpWithinHeight_IsAccepted()
    {
        // A 0.4 m riser indoors: the stair tread is a second floor polygon.
        CellSurface stairs = new CellBuilder(0xA9B40100u).Floor(10, 10, 12, 14, 0).Floor(12, 10, 14, 14, 0.4f).Build();
        PhysicsEngine engine = MakeEngine(FlatTerrain(-20f), stairs);

        ResolveResult r = engine.Resolve(new Vector3(11.8f, 12, 0), 0xA9B40100u, new Vector3(0.4f, 0, 0), Step);

        r.Position.Should().Be(new Vector3(12.2f, 12, 0.4f));
        r.CellId.Should().Be(0xA9B40100u);
    }

    [Fact]
    public void Resolve_StepExactlyTheStepHeight_IsAccepted()
    {
        CellSurface stairs = new CellBuilder(0xA9B40100u).Floor(10, 10, 12, 14, 0).Floor(12, 10, 14, 14, 0.5f).Build();
        PhysicsEngine engine = MakeEngine(FlatTerrain(-20f), stairs);

        engine.Resolve(new Vector3(11.8f, 12, 0), 0xA9B40100u, new Vector3(0.4f, 0, 0), 0.5f).Position.Z.Should().Be(0.5f);
        engine.Resolve(new Vector3(11.8f, 12, 0), 0xA9B40100u, new Vector3(0.4f, 0, 0), 0.49f).Position.Should().Be(new Vector3(11.8f, 12, 0));
    }

    [Fact]
    public void Resolve_BlockedByWall_HorizontalMovementRejected()
    {
        // Outdoors: a cliff rising 100 m over 24 m; a 1 m step climbs 4.2 m.
        float[] table = LinearTable();
        PhysicsEngine engine = MakeEngine(new TerrainSurface(Heights((x, _) => x <= 4 ? 0 : 50), table, Holtburg));
        var start = new Vector3(96f, 50, 0);

        ResolveResult r = engine.Resolve(start, 0xA9B40000u | 0x0023u, new Vector3(1, 0, 0), Step);

        r.Position.Should().Be(start, "the rise exceeds the step height");
        r.IsOnGround.Should().BeTrue();
        r.CellId.Should().Be(0xA9B40023u);

        // Indoors: a 1 m platform.
        CellSurface room = new CellBuilder(0xA9B40100u).Floor(10, 10, 12, 14, 0).Floor(12, 10, 14, 14, 1f).Build();
        engine = MakeEngine(FlatTerrain(-20f), room);
        engine.Resolve(new Vector3(11.8f, 12, 0), 0xA9B40100u, new Vector3(0.4f, 0, 0), Step)
            .Should().Be(new ResolveResult(new Vector3(11.8f, 12, 0), 0xA9B40100u, true) { Outcome = ResolveOutcome.StepTooHigh });
    }

    [Fact]
    public void Resolve_StepDown_SnapsToLowerGround()
    {
        CellSurface room = new CellBuilder(0xA9B40100u).Floor(10, 10, 12, 14, 2).Floor(12, 10, 14, 14, 0f).Build();
        PhysicsEngine engine = MakeEngine(FlatTerrain(-20f), room);
        engine.Resolve(new Vector3(11.8f, 12, 2), 0xA9B40100u, new Vector3(0.4f, 0, 0), Step).Position.Z.Should().Be(0f);
    }

    /// <summary>A 4 × 4 m room at (20..24, 20..24), floor at terrain height, a doorway to the outdoors on its west wall (y 21..23).</summary>
    private static CellSurface RoomWithWestDoor(float floorZ) =>
        new CellBuilder(0xA9B40100u)
            .Floor(20, 20, 24, 24, floorZ)
            .Portal(0xFFFF, new Vector3(22, 22, floorZ + 1), Wall(20, 23, 20, 21, floorZ, floorZ + 2.5f))
            .Build();

    [Fact]
    public void Resolve_OutdoorToIndoor_CellIdChangesToIndoor()
    {
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f), RoomWithWestDoor(50.2f));

        ResolveResult r = engine.Resolve(new Vector3(19.8f, 22, 50), 0xA9B40000u, new Vector3(0.5f, 0, 0), Step);

        r.CellId.Should().Be(0xA9B40100u);
        r.Position.Should().Be(new Vector3(20.3f, 22, 50.2f));
        r.IsOnGround.Should().BeTrue();
    }

    [Fact]
    public void Resolve_IndoorToOutdoor_CellIdChangesToOutdoor()
    {
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f), RoomWithWestDoor(50.2f));

        ResolveResult r = engine.Resolve(new Vector3(20.3f, 22, 50.2f), 0xA9B40100u, new Vector3(-0.5f, 0, 0), Step);

        r.CellId.Should().Be(0xA9B40001u, "(19.8, 22) is outdoor cell 0x0001");
        r.Position.Should().Be(new Vector3(19.8f, 22, 50f));
    }

    [Fact]
    public void Resolve_IndoorThroughWall_IsRejected()
    {
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f), RoomWithWestDoor(50.2f));
        var start = new Vector3(20.3f, 20.5f, 50.2f); // south of the doorway (y 21..23)

        engine.Resolve(start, 0xA9B40100u, new Vector3(-0.5f, 0, 0), Step)
            .Should().BeEquivalentTo(new { Position = start, CellId = 0xA9B40100u, IsOnGround = true, Outcome = ResolveOutcome.Wall });
        engine.Resolve(start, 0xA9B40100u, new Vector3(0, -0.6f, 0), Step)
            .Should().Be(new ResolveResult(start, 0xA9B40100u, true) { Outcome = ResolveOutcome.Wall }, "no portal on the south wall");
    }

    [Fact]
    public void Resolve_OutdoorFloorOutOfStepRange_IsNotAnEntry()
    {
        // A cellar 3 m below the terrain under the same XY, and an attic 3 m above.
        CellSurface cellar = new CellBuilder(0xA9B40100u).Floor(20, 20, 24, 24, 47).Build();
        CellSurface attic = new CellBuilder(0xA9B40101u).Floor(20, 20, 24, 24, 53).Build();
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f), cellar, attic);

        ResolveResult r = engine.Resolve(new Vector3(19.8f, 22, 50), 0xA9B40000u, new Vector3(0.5f, 0, 0), Step);

        r.CellId.Should().Be(0xA9B40001u);
        r.Position.Z.Should().Be(50f);
    }

    [Fact]
    public void Resolve_OutdoorOverlappingFloors_NearestToMoverWins()
    {
        CellSurface low = new CellBuilder(0xA9B40100u).Floor(20, 20, 24, 24, 49.8f).Build();
        CellSurface high = new CellBuilder(0xA9B40101u).Floor(20, 20, 24, 24, 50.1f).Build();
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f), high, low);

        ResolveResult r = engine.Resolve(new Vector3(19.8f, 22, 50), 0xA9B40000u, new Vector3(0.5f, 0, 0), Step);

        r.CellId.Should().Be(0xA9B40101u, "50.1 is 0.1 m from the mover's 50, 49.8 is 0.2 m");
        r.Position.Z.Should().Be(50.1f);
    }

    [Fact]
    public void Resolve_NotOnGround_OverEmptySpace()
    {
        // A floorless cell (a shaft) whose only portal leads to a cell the engine does not have.
        CellSurface shaft = new CellBuilder(0xA9B40100u)
            .Physics(Wall(20, 20, 24, 20, 40, 44))
            .Portal(0x0105, new Vector3(22, 22, 42), Square(20, 20, 24, 24, 40))
            .Build();
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f), shaft);
        var pos = new Vector3(22, 22, 43);

        ResolveResult r = engine.Resolve(pos, 0xA9B40100u, new Vector3(0.1f, 0, 0), Step);

        r.IsOnGround.Should().BeFalse();
        r.Position.Should().Be(pos, "XY kept, Z unchanged: the caller's gravity acts");
        r.CellId.Should().Be(0xA9B40100u);
    }

    [Fact]
    public void Resolve_AcrossLandblockSeam_NeighbourTerrainAndPrefix()
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(0xA9B4FFFFu, FlatTerrain(50f, 0xA9B4FFFFu), []);
        engine.AddLandblock(0xAAB4FFFFu, FlatTerrain(51f, 0xAAB4FFFFu), []);

        ResolveResult r = engine.Resolve(new Vector3(191, 10, 50), 0xA9B40039u, new Vector3(2, 0, 0), 1.5f);

        r.CellId.Should().Be(0xAAB40001u);
        r.Position.Should().Be(new Vector3(193, 10, 51));
        engine.Resolve(new Vector3(191, 10, 50), 0xA9B40039u, Vector3.Zero, 1.5f).CellId.Should().Be(0xA9B40039u);
    }

    [Fact]
    public void Resolve_IntoUnloadedLandblock_IsRejectedAndMoverStays()
    {
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f));
        var pos = new Vector3(191.5f, 10, 50);

        engine.Resolve(pos, 0xA9B40039u, new Vector3(1, 0, 0), Step)
            .Should().Be(new ResolveResult(pos, 0xA9B40039u, true) { Outcome = ResolveOutcome.UnloadedAhead });
        engine.Resolve(new Vector3(0.5f, 0.5f, 50), 0xA9B40001u, new Vector3(-1, -1, 0), Step)
            .Position.Should().Be(new Vector3(0.5f, 0.5f, 50));
    }

    [Fact]
    public void Resolve_WorldFrames_GlobalAndCentredAgree()
    {
        var centred = new PhysicsEngine(Holtburg);
        var global = new PhysicsEngine();
        byte[] heights = RandomHeights(new Random(1));
        foreach (PhysicsEngine engine in new[] { centred, global })
        {
            engine.AddLandblock(Holtburg, new TerrainSurface(heights, NonLinearTable(), Holtburg), []);
        }

        Vector3 offset = global.GetLandblockOrigin(Holtburg);
        offset.Should().Be(new Vector3(0xA9 * 192f, 0xB4 * 192f, 0));
        centred.GetLandblockOrigin(Holtburg).Should().Be(Vector3.Zero);

        ResolveResult local = centred.Resolve(new Vector3(50, 60, 0), 0xA9B40000u, new Vector3(0.25f, 0.5f, 0), 1000f);
        ResolveResult world = global.Resolve(new Vector3(50, 60, 0) + offset, 0xA9B40000u, new Vector3(0.25f, 0.5f, 0), 1000f);

        world.CellId.Should().Be(local.CellId);
        (world.Position - offset).X.Should().BeApproximately(local.Position.X, 0.01f);
        world.Position.Z.Should().BeApproximately(local.Position.Z, 0.05f, "the same ground, up to the ~4 mm rounding of a global XY");
    }

    [Fact]
    public void Resolve_CellIdLowBitsZero_OutdoorCellComputedFromPosition()
    {
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f));
        engine.Resolve(new Vector3(30, 50, 50), 0, Vector3.Zero, Step).CellId.Should().Be(0xA9B4000Bu);
    }

    [Fact]
    public void AddLandblock_ThenRemove_ResolveNoLongerFindsIt()
    {
        CellSurface room = RoomWithWestDoor(50.2f);
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f), room);
        engine.LandblockCount.Should().Be(1);
        engine.ContainsLandblock(0xA9B40000u).Should().BeTrue();

        engine.RemoveLandblock(Holtburg);
        engine.RemoveLandblock(Holtburg); // idempotent

        engine.LandblockCount.Should().Be(0);
        engine.Resolve(new Vector3(19.8f, 22, 10), 0xA9B40000u, new Vector3(0.5f, 0, 0), Step)
            .Should().Be(new ResolveResult(new Vector3(19.8f, 22, 10), 0xA9B40001u, true) { Outcome = ResolveOutcome.Held }, "unloaded land holds the mover");

        engine.AddLandblock(Holtburg, FlatTerrain(50f), [room]);
        engine.Resolve(new Vector3(19.8f, 22, 50), 0xA9B40000u, new Vector3(0.5f, 0, 0), Step).CellId.Should().Be(0xA9B40100u);
    }

    [Fact]
    public void AddLandblock_Twice_ReplacesWithoutDoubling()
    {
        PhysicsEngine engine = MakeEngine(FlatTerrain(50f));
        engine.AddLandblock(Holtburg, FlatTerrain(60f), []);

        engine.LandblockCount.Should().Be(1);
        engine.Resolve(new Vector3(10, 10, 60), 0, Vector3.Zero, Step).Position.Z.Should().Be(60f);
    }

    [Fact]
    public void Resolve_BilinearTerrainSurface_IsUsedAsGiven()
    {
        // The spec's own constructor (no landblock id) works in the engine too.
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, new TerrainSurface(Heights((x, y) => x + y), LinearTable()), []);
        engine.Resolve(new Vector3(12, 12, 2), 0, Vector3.Zero, Step).Position.Z.Should().BeApproximately(2f, 1e-5f);
    }

    [Fact]
    public void Resolve_AdjoiningRooms_WallBesideTheDoorwayBlocks()
    {
        // Room A (x 10..14) and room B (x 14..18) share the wall x = 14; its doorway spans y 11.5..12.5.
        var inA = new Vector3(12, 12, 1);
        var inB = new Vector3(16, 12, 1);
        CellSurface a = new CellBuilder(0xA9B40100u).Floor(10, 10, 14, 14, 0).Portal(0x0101, inA, Wall(14, 11.5f, 14, 12.5f, 0, 2)).Build();
        CellSurface b = new CellBuilder(0xA9B40101u).Floor(14, 10, 18, 14, 0).Portal(0x0100, inB, Wall(14, 12.5f, 14, 11.5f, 0, 2)).Build();
        PhysicsEngine engine = MakeEngine(FlatTerrain(-20f), a, b);

        engine.Resolve(new Vector3(13.9f, 12f, 0), 0xA9B40100u, new Vector3(0.2f, 0, 0), Step).CellId
            .Should().Be(0xA9B40101u, "through the doorway");
        var besideDoor = new Vector3(13.9f, 10.5f, 0);
        engine.Resolve(besideDoor, 0xA9B40100u, new Vector3(0.2f, 0, 0), Step)
            .Should().BeEquivalentTo(
                new { Position = besideDoor, CellId = 0xA9B40100u, IsOnGround = true, Outcome = ResolveOutcome.Wall },
                "beside the doorway is the wall, though B's floor lies beyond it");
        engine.Resolve(besideDoor, 0xA9B40100u, new Vector3(0.2f, 0, 0), Step, MovementOptions.Player).Position.Should().Be(besideDoor);
    }
}
