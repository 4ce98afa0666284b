using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// Issue 8, defects 1, 2, 4 and 9: a refused move never reports ground in mid-air, an accepted move
/// never ends where the next call finds no floor, doors only never lets a mover into a closed box,
/// and hostile portal graphs cannot stall a call. Each reproduces the case found by trying to break
/// the engine.
/// </summary>
[Trait("Mutation", "ObjectQueries")]
[Trait("Mutation", "PortalTraversal")]
public class GroundHonestyTests
{
    private const uint Lb = 0xA9B4FFFFu;

    /// <summary>Table 2·i; terrain 20 m for x &lt; 120 and 200 m from x = 120: a cliff (landblock-local).</summary>
    private static TerrainSurface Cliff() =>
        new(Heights((x, _) => x >= 5 ? 100 : 10), LinearTable(), Lb);

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void Resolve_RefusedMoveInMidAirOutdoors_IsNotOnTheGround(bool withOptions)
    {
        var engine = new PhysicsEngine(Lb);
        engine.AddLandblock(Lb, Cliff(), []);
        var pos = new Vector3(96, 50, 30);
        var delta = new Vector3(5, 0, 0);

        ResolveResult r = withOptions
            ? engine.Resolve(pos, 0, delta, 0.5f, new MovementOptions { StepDownHeight = 0f })
            : engine.Resolve(pos, 0, delta, 0.5f);

        r.Position.Should().Be(pos, "the move into the cliff is refused and the mover keeps its place");
        r.IsOnGround.Should().BeFalse($"the mover is 10 m above the ground at 20 m: {r}");
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void Resolve_RefusedMoveInMidAirIndoors_IsNotOnTheGround(bool withOptions)
    {
        var engine = new PhysicsEngine(Lb);
        CellSurface room = new CellBuilder(0xA9B40100, new Vector3(40, 50, 10)).Floor(-5, -5, 5, 5, 0).Build();
        engine.AddLandblock(Lb, FlatTerrain(0f), [room]);
        var pos = new Vector3(40 + 4.5f, 50, 20); // 10 m above the floor, next to the east wall
        var delta = new Vector3(2, 0, 0);

        ResolveResult r = withOptions
            ? engine.Resolve(pos, 0xA9B40100, delta, 0.5f, new MovementOptions { StepDownHeight = 0f })
            : engine.Resolve(pos, 0xA9B40100, delta, 0.5f);

        r.Position.Should().Be(pos);
        r.CellId.Should().Be(0xA9B40100);
        r.IsOnGround.Should().BeFalse($"the mover is 10 m above the floor at 10 m: {r}");
    }

    [Fact]
    public void Resolve_FallingMoverRefusedAtTheWall_LandsWhenItReachesTheFloor()
    {
        // A mover falling along a wall, pushing into it each frame, must land on the floor (not
        // hover, not sink through): once its Z reaches the floor it stands on it.
        var engine = new PhysicsEngine(Lb);
        CellSurface room = new CellBuilder(0xA9B40100, new Vector3(40, 50, 10)).Floor(-5, -5, 5, 5, 0).Build();
        engine.AddLandblock(Lb, FlatTerrain(0f), [room]);
        var options = new MovementOptions { StepDownHeight = 0f };
        var pos = new Vector3(44.9f, 50, 10.05f);
        ResolveResult above = engine.Resolve(pos, 0xA9B40100, new Vector3(1, 0, 0), 0.5f, options);
        above.IsOnGround.Should().BeFalse($"5 cm above the floor: {above}");

        ResolveResult below = engine.Resolve(pos with { Z = 9.97f }, 0xA9B40100, new Vector3(1, 0, 0), 0.5f, options);
        below.IsOnGround.Should().BeTrue($"3 cm below the floor the fall is over: {below}");
        below.Position.Z.Should().Be(10f, "the mover lands on the floor");
    }

    [Fact]
    public void Resolve_AcceptedMoveAtTheFloorEdgeInTheGlobalFrame_StaysOnTheFloorWhenResolvedAgain()
    {
        var engine = new PhysicsEngine();
        CellSurface room = new CellBuilder(0xA9B40100, new Vector3(40.0015f, 50, 10)).Floor(0, 0, 10, 10, 0).Build();
        engine.AddLandblock(Lb, FlatTerrain(0f), [room]);

        // Landblock-local x 45 + 5.0016 = 50.0016: 0.1 mm past the floor's east edge (within the
        // 0.2 mm edge tolerance); the world x 32498.0016 rounds to 32498.0039 (float spacing 3.9 mm).
        ResolveResult r = engine.Resolve(new Vector3(32493, 34615, 10), 0xA9B40100, new Vector3(5.0016f, 0, 0), 0.5f);
        ResolveResult again = engine.Resolve(r.Position, r.CellId, Vector3.Zero, 0.5f);

        (again.Position, again.CellId, again.IsOnGround).Should().Be((r.Position, r.CellId, r.IsOnGround), $"re-resolving {r} in place must return it (got {again})");
        r.IsOnGround.Should().BeTrue();
        r.CellId.Should().Be(0xA9B40100);
    }

    [Theory]
    [InlineData(-1f)] // from downhill (west), walking east
    [InlineData(1f)]  // from uphill (east), walking west
    public void Resolve_DoorsOnlyOnSlopingGround_NeverEntersAClosedBox(float side)
    {
        // Terrain rising 0.5 m per metre eastward (heights 12·x at 24 m per vertex with table 1·i),
        // a closed 10 × 10 box with no portals whose floor is level with the ground at its centre.
        float[] table = new float[256];
        for (int i = 0; i < 256; i++)
        {
            table[i] = i;
        }

        var terrain = new TerrainSurface(Heights((x, _) => 12 * x), table, Lb);
        float centreZ = terrain.SampleZ(96, 96);
        CellSurface box = new CellBuilder(0xA9B40100, new Vector3(96, 96, centreZ)).Floor(-5, -5, 5, 5, 0).Build();
        var engine = new PhysicsEngine(Lb);
        engine.AddLandblock(Lb, terrain, [box]);

        for (float y = 91.5f; y <= 100.5f; y += 1.5f)
        {
            var pos = new Vector3(96 + (side * 12), y, terrain.SampleZ(96 + (side * 12), y));
            uint cell = 0;
            var trace = new System.Text.StringBuilder();
            for (int frame = 0; frame < 200; frame++)
            {
                ResolveResult r = engine.Resolve(pos, cell, new Vector3(-side * 0.1f, 0, 0), 0.5f, MovementOptions.Player);
                trace.Append(r).Append('\n');
                r.CellId.Should().NotBe(0xA9B40100, $"{trace} walking {(side < 0 ? "east" : "west")} along y = {y}, frame {frame} from {pos}: the box has no door");
                pos = r.Position;
                cell = r.CellId;
            }
        }
    }

    [Fact]
    public async Task Resolve_ChainOfShaftsWithManyOpenings_VisitsABoundedNumberOfCells()
    {
        // Five floorless shafts, each with 60 parallel floor openings into the next (the last's lead
        // back up): no floor anywhere, so an unbounded search visits 60⁴ cells. It is bounded in
        // breadth too, so the call finishes, with nothing under the mover.
        var cells = new List<CellSurface>();
        const int shafts = 5, openings = 60;
        for (int s = 0; s < shafts; s++)
        {
            var b = new CellBuilder(0xA9B40100u + (uint)s, new Vector3(50, 50, 100 - (s * 0.1f)));
            for (int k = 0; k < openings; k++)
            {
                b.Portal((ushort)(0x0100 + (s + 1 < shafts ? s + 1 : s - 1)), new Vector3(0, 0, 1), Square(-2, -2, 2, 2, 0));
            }

            cells.Add(b.Build());
        }

        var engine = new PhysicsEngine(Lb);
        engine.AddLandblock(Lb, FlatTerrain(0f), cells);

        // A guard against a hang, not a speed claim (ResolveBenchmarks.HostileShafts measures it).
        ResolveResult r = await Task.Run(() => engine.Resolve(new Vector3(50, 50, 100), 0xA9B40100, new Vector3(0.1f, 0, 0), 0.5f))
            .WaitAsync(TimeSpan.FromSeconds(0.5));
        r.IsOnGround.Should().BeFalse($"no cell has a floor: {r}");
    }
}
