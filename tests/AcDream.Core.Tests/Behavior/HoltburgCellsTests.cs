using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>The real Holtburg cells (landblock 0xA9B4), on flat terrain at the cottage's floor height.</summary>
[Trait("Mutation", "PortalTraversal")]
public class HoltburgCellsTests
{
    private const float PlayerStep = 0.5f;
    private const float GroundZ = 94f;

    /// <summary>World = 0xA9B4-local; the south neighbour 0xA9B3 is loaded too (the cellar reaches past the seam).</summary>
    private static PhysicsEngine MakeEngine()
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), HoltburgCells.Surfaces());
        engine.AddLandblock(0xA9B3FFFFu, FlatTerrain(GroundZ, 0xA9B3FFFFu), []);
        return engine;
    }

    [Theory]
    [InlineData(0xA9B40143u, 138.0f, 10.0f, 94.0f)]   // cottage ground floor
    [InlineData(0xA9B40143u, 138.0f, 5.0f, 94.0f)]
    [InlineData(0xA9B40142u, 139.0f, 13.3f, 95.0f)]   // raised room
    [InlineData(0xA9B40140u, 136.5f, 15.0f, 95.0f)]
    [InlineData(0xA9B4014Bu, 130.0f, 12.0f, 97.0f)]   // upper floor
    [InlineData(0xA9B4014Du, 140.0f, 10.0f, 97.0f)]
    [InlineData(0xA9B4014Eu, 139.4f, 3.7f, 98.0f)]    // upper door
    [InlineData(0xA9B4014Fu, 139.4f, 19.2f, 94.85f)]  // north door
    [InlineData(0xA9B40147u, 138.0f, 6.0f, 90.95f)]   // cellar
    [InlineData(0xA9B40147u, 141.0f, -0.5f, 90.95f)]  // cellar past the landblock's south seam
    [InlineData(0xA9B40148u, 133.5f, 6.0f, 90.0f)]    // foot of the ramp
    [InlineData(0xA9B40148u, 135.125f, 6.0f, 90.475f)] // half-way down the ramp
    [InlineData(0xA9B40148u, 136.75f, 6.0f, 90.95f)]  // top of the ramp, the cellar's level
    [InlineData(0xA9B40149u, 127.5f, 5.0f, 90.0f)]
    [InlineData(0xA9B40174u, 158.0f, 8.0f, 90.001f)]  // building B's cellar
    [InlineData(0xA9B40171u, 156.0f, 12.0f, 94.0f)]
    public void SampleFloorZ_RealCell_MatchesGameData(uint cellId, float x, float y, float expected)
    {
        HoltburgCells.Surface(cellId).SampleFloorZ(x, y)!.Value.Should().BeApproximately(expected, 1e-3f, $"floor of 0x{cellId:X8} at ({x}, {y})");
    }

    [Theory]
    [InlineData(0xA9B40146u)]
    [InlineData(0xA9B4014Au)]
    [InlineData(0xA9B40175u)]
    public void SampleFloorZ_ShaftCells_HaveNoFloor(uint cellId)
    {
        CellSurface shaft = HoltburgCells.Surface(cellId);
        shaft.HasFloor.Should().BeFalse($"0x{cellId:X8} is a shaft between two floors");
    }

    [Fact]
    public void Resolve_CellarUnderGroundFloor_FloorNearestTheMoverWins()
    {
        // (138, 6) is over both the ground floor 0x0143 (94.0) and the cellar 0x0147 (90.95).
        HoltburgCells.Surface(0xA9B40143u).SampleFloorZ(138, 6)!.Value.Should().BeApproximately(94f, 1e-4f);
        HoltburgCells.Surface(0xA9B40147u).SampleFloorZ(138, 6).Should().BeApproximately(90.95f, 1e-4f);

        PhysicsEngine engine = MakeEngine();
        ResolveResult upstairs = engine.Resolve(new Vector3(138, 6, 94), 0xA9B40143u, new Vector3(0.2f, 0, 0), PlayerStep);
        ResolveResult downstairs = engine.Resolve(new Vector3(138, 6, 90.95f), 0xA9B40147u, new Vector3(0.2f, 0, 0), PlayerStep);

        upstairs.CellId.Should().Be(0xA9B40143u);
        upstairs.Position.X.Should().BeApproximately(138.2f, 1e-4f);
        upstairs.Position.Z.Should().BeApproximately(94f, 1e-4f, "the ground floor, not the cellar under it");
        downstairs.CellId.Should().Be(0xA9B40147u);
        downstairs.Position.Z.Should().BeApproximately(90.95f, 1e-4f);
    }

    [Fact]
    public void Portals_EveryTarget_IsInTheSetOutdoorsOrAKnownMissingNeighbour()
    {
        var ids = HoltburgCells.Fixtures.Keys.ToHashSet();
        foreach (CellSurface cell in HoltburgCells.Surfaces())
        {
            cell.Portals.Should().NotBeEmpty();
            foreach (CellPortalInfo portal in cell.Portals)
            {
                bool known = ids.Contains(portal.TargetCellId) || portal.TargetCellId is 0xA9B4FFFFu or 0xA9B4013Fu or 0xA9B4016Fu;
                known.Should().BeTrue($"0x{cell.CellId:X8} has a portal to 0x{portal.TargetCellId:X8}");
                portal.PortalNormal.Length().Should().BeApproximately(1f, 1e-4f);
            }
        }
    }

    [Fact]
    public void Portals_PairedPortals_CoincideAndFaceOpposite()
    {
        // A portal and its partner in the neighbour are the same opening seen from both sides.
        Dictionary<uint, CellSurface> cells = HoltburgCells.Surfaces().ToDictionary(c => c.CellId);
        int pairs = 0;
        foreach (CellSurface cell in cells.Values)
        {
            foreach (CellPortalInfo portal in cell.Portals)
            {
                if (!cells.TryGetValue(portal.TargetCellId, out CellSurface? other))
                {
                    continue;
                }

                CellPortalInfo back = other.Portals.Where(p => p.TargetCellId == cell.CellId)
                    .MinBy(p => Vector3.Distance(p.PortalOrigin, portal.PortalOrigin));
                Vector3.Distance(back.PortalOrigin, portal.PortalOrigin).Should().BeLessThan(0.01f, $"0x{cell.CellId:X8} ↔ 0x{other.CellId:X8}");
                Vector3.Dot(back.PortalNormal, portal.PortalNormal).Should().BeApproximately(-1f, 0.01f, $"0x{cell.CellId:X8} ↔ 0x{other.CellId:X8} face opposite ways");
                pairs++;
            }
        }

        pairs.Should().Be(38, "the fixture README counts 38 portals whose neighbour is in the set");
    }

    [Fact]
    public void Resolve_WalkThroughWestDoorIntoMainRoomAndDoorwayAndBackOut_FollowsPortalGraph()
    {
        PhysicsEngine engine = MakeEngine();
        var pos = new Vector3(134.0f, 5.15f, GroundZ);
        uint cell = 0xA9B40000u;
        var visited = new List<uint>();

        void Walk(Vector3 target)
        {
            for (int frame = 0; frame < 400 && Vector2.Distance(new(pos.X, pos.Y), new(target.X, target.Y)) > 1e-3f; frame++)
            {
                Vector2 toTarget = new Vector2(target.X, target.Y) - new Vector2(pos.X, pos.Y);
                Vector2 move = toTarget.Length() > 0.1f ? Vector2.Normalize(toTarget) * 0.1f : toTarget;
                ResolveResult r = engine.Resolve(pos, cell, new Vector3(move, 0), PlayerStep);
                r.Position.Should().NotBe(pos, $"frame {frame} towards {target} from {pos} in 0x{cell:X8} must not be rejected");
                (pos, cell) = (r.Position, r.CellId);
                r.IsOnGround.Should().BeTrue();
                ExpectOnReportedSurface(r);
                if (visited.Count == 0 || visited[^1] != Simplify(cell))
                {
                    visited.Add(Simplify(cell));
                }
            }
        }

        Walk(new Vector3(138.5f, 5.15f, 0));  // in through 0x0145 into 0x0143
        Walk(new Vector3(138.5f, 10.0f, 0));  // across the main room
        Walk(new Vector3(136.5f, 10.0f, 0));  // into the doorway 0x0144
        Walk(new Vector3(138.5f, 10.0f, 0));  // back into the room
        Walk(new Vector3(138.5f, 5.15f, 0));
        Walk(new Vector3(134.0f, 5.15f, 0));  // out through 0x0145

        visited.Select(c => $"0x{c:X4}").Should().Equal(
            ["0x0000", "0x0145", "0x0143", "0x0144", "0x0143", "0x0145", "0x0000"],
            "outdoors → west door → main room → doorway → main room → west door → outdoors");

        static uint Simplify(uint id) => (id & 0xFFFF) < 0x100 ? 0 : id & 0xFFFF;
    }

    [Fact]
    public void Resolve_DoorwayFlipsCellAtThePortalPlane()
    {
        PhysicsEngine engine = MakeEngine();

        // 0x0145's outdoor portal is the plane x = 136.3.
        engine.Resolve(new Vector3(136.25f, 5.15f, GroundZ), 0xA9B40000u, new Vector3(0.04f, 0, 0), PlayerStep)
            .CellId.Should().Be(0xA9B40029u, "x 136.29 is still outdoors (cell cx 5, cy 0: 0x29)");
        engine.Resolve(new Vector3(136.25f, 5.15f, GroundZ), 0xA9B40000u, new Vector3(0.06f, 0, 0), PlayerStep)
            .CellId.Should().Be(0xA9B40145u, "x 136.31 is over the doorway's floor");
        engine.Resolve(new Vector3(136.31f, 5.15f, GroundZ), 0xA9B40145u, new Vector3(-0.02f, 0, 0), PlayerStep)
            .CellId.Should().Be(0xA9B40029u, "crossing the outdoor portal's plane leaves at once");
    }

    [Fact]
    public void Resolve_IntoMissingNeighbour_IsRejected()
    {
        // 0x0144's west portal leads to 0x013F, which the set lacks.
        PhysicsEngine engine = MakeEngine();
        var pos = new Vector3(136.5f, 10f, GroundZ);

        engine.Resolve(pos, 0xA9B40144u, new Vector3(-0.4f, 0, 0), PlayerStep)
            .Should().Be(new ResolveResult(pos, 0xA9B40144u, true) { Outcome = ResolveOutcome.Wall });
    }

    [Fact]
    public void Resolve_OverStairwellOpening_PassesShaftToCellarFloor()
    {
        // 0x0143's floor opening (x 140.5–142.1, y 3.9–8.7) → shaft 0x0146 (no floor) → cellar 0x0147.
        PhysicsEngine engine = MakeEngine();

        ResolveResult r = engine.Resolve(new Vector3(140.3f, 6f, GroundZ), 0xA9B40143u, new Vector3(0.5f, 0, 0), PlayerStep);

        r.CellId.Should().Be(0xA9B40147u);
        r.Position.X.Should().BeApproximately(140.8f, 1e-4f);
        r.Position.Z.Should().BeApproximately(90.95f, 1e-4f, "the stairs are a separate object; the mover lands on the cellar floor");
        r.IsOnGround.Should().BeTrue();
    }

    [Fact]
    public void Resolve_BuildingBShaft_DropsToCellar0174()
    {
        PhysicsEngine engine = MakeEngine();

        ResolveResult r = engine.Resolve(new Vector3(155.2f, 8f, GroundZ), 0xA9B40171u, new Vector3(-0.5f, 0, 0), PlayerStep);

        r.CellId.Should().Be(0xA9B40174u);
        r.Position.Z.Should().BeApproximately(90.001f, 1e-4f, "0x0174's floor is at cell-local z −3.999");
    }

    [Fact]
    public void Resolve_CellarPastSouthSeam_StaysInCellarAndIsNotEnteredFromNeighbourTerrain()
    {
        PhysicsEngine engine = MakeEngine();

        // Walking inside the cellar across y = 0: still 0x0147, on its floor.
        ResolveResult inside = engine.Resolve(new Vector3(141f, 0.3f, 90.95f), 0xA9B40147u, new Vector3(0, -0.8f, 0), PlayerStep);
        inside.CellId.Should().Be(0xA9B40147u);
        inside.Position.Y.Should().BeApproximately(-0.5f, 1e-4f);
        inside.Position.Z.Should().BeApproximately(90.95f, 1e-4f);

        // Outdoors in 0xA9B3 over the cellar's footprint: terrain, never the cellar.
        ResolveResult outside = engine.Resolve(new Vector3(141f, -0.3f, GroundZ), 0xA9B30000u, new Vector3(0, -0.4f, 0), PlayerStep);
        outside.CellId.Should().Be(0xA9B30000u | 0x0030u, "(141, 191.3) of 0xA9B3 is outdoor cell cx 5, cy 7");
        outside.Position.Z.Should().Be(GroundZ);
    }

    private static void ExpectOnReportedSurface(ResolveResult r)
    {
        if ((r.CellId & 0xFFFF) >= 0x100)
        {
            float? floor = HoltburgCells.Surface(r.CellId).SampleFloorZ(r.Position.X, r.Position.Y, r.Position.Z);
            floor.Should().NotBeNull($"{r.Position} must be over the floor of 0x{r.CellId:X8}");
            r.Position.Z.Should().BeApproximately(floor!.Value, 1e-4f);
        }
        else
        {
            r.Position.Z.Should().Be(GroundZ);
        }
    }
}
