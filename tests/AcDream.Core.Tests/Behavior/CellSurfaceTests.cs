using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

[Trait("Mutation", "PortalTraversal")]
public class CellSurfaceTests
{
    private const uint CellId = 0xA9B40100u;

    private static CellSurface FlatSquareAt10() => new CellBuilder(CellId).Floor(-5, -5, 5, 5, 10).Build();

    [Fact]
    public void SampleFloorZ_InsidePolygon_ReturnsFloorZ()
    {
        FlatSquareAt10().SampleFloorZ(0, 0).Should().Be(10f);
    }

    [Fact]
    public void SampleFloorZ_OutsidePolygon_ReturnsNull()
    {
        FlatSquareAt10().SampleFloorZ(100, 100).Should().BeNull();
        FlatSquareAt10().SampleFloorZ(5.01f, 0).Should().BeNull("1 cm past the edge is off the floor");
    }

    [Theory]
    [InlineData(5f, 0f)]
    [InlineData(-5f, -5f)]
    [InlineData(5f, 5f)]
    [InlineData(0f, -5f)]
    [InlineData(5.0001f, 0f)] // within the 0.2 mm edge tolerance
    public void SampleFloorZ_OnEdgeOrVertex_ReturnsFloor(float x, float y)
    {
        FlatSquareAt10().SampleFloorZ(x, y).Should().Be(10f, $"({x}, {y}) is on the floor's boundary");
    }

    [Theory]
    [InlineData(0f, 0f, 11f)]
    [InlineData(-2.5f, 3f, 10.5f)]
    [InlineData(2.5f, -1f, 11.5f)]
    [InlineData(-5f, 0f, 10f)]
    [InlineData(5f, 0f, 12f)]
    public void SampleFloorZ_SlopedFloor_InterpolatesBarycentrically(float x, float y, float expected)
    {
        // A ramp rising 2 m over 10 m along X (normal Z ≈ 0.98: walkable).
        CellSurface cell = new CellBuilder(CellId)
            .Physics(new(-5, -5, 10), new(5, -5, 12), new(5, 5, 12), new(-5, 5, 10))
            .Build();

        cell.SampleFloorZ(x, y)!.Value.Should().BeApproximately(expected, 1e-4f, $"ramp Z at ({x}, {y})");
    }

    [Fact]
    public void SampleFloorZ_SlopedTriangle_MatchesPlaneAtInteriorPoints()
    {
        // Vertices at different heights: Z on the plane through them.
        Vector3 a = new(0, 0, 1), b = new(4, 0, 2), c = new(0, 4, 3);
        CellSurface cell = new CellBuilder(CellId).Physics(a, b, c).Build();

        // Plane: z = 1 + x/4 + y/2.
        foreach ((float x, float y) in new[] { (1f, 1f), (2f, 0.5f), (0.5f, 3f), (4f / 3, 4f / 3) })
        {
            cell.SampleFloorZ(x, y)!.Value.Should().BeApproximately(1f + (x / 4) + (y / 2), 1e-5f, $"({x}, {y})");
        }
    }

    [Fact]
    public void SampleFloorZ_WallsAndCeilings_AreNeverFloors()
    {
        CellSurface cell = new CellBuilder(CellId)
            .Physics(Wall(-5, 0, 5, 0, 10, 13))                          // vertical wall across the middle
            .Physics(Square(-5, -5, 5, 5, 13).Reverse().ToArray())        // ceiling: faces down
            .Physics(new(-5, -5, 10), new(5, -5, 30), new(5, 5, 30), new(-5, 5, 10)) // 63° slope: too steep
            .Build();

        cell.SampleFloorZ(0, 0).Should().BeNull("a wall, a ceiling and a too-steep slope carry no one");
        cell.HasFloor.Should().BeFalse();
    }

    [Fact]
    public void SampleFloorZ_ReversedWindingFloor_IsACeiling()
    {
        new CellBuilder(CellId).Physics(Square(-5, -5, 5, 5, 10).Reverse().ToArray()).Build()
            .SampleFloorZ(0, 0).Should().BeNull("clockwise from above faces down");
    }

    [Fact]
    public void SampleFloorZ_SlopeAtWalkableLimit_IsAFloor()
    {
        // Normal Z just above FloorZ (48.4°): rise tan(48°) = 1.1106 per metre.
        float rise = MathF.Tan(48f * MathF.PI / 180f) * 2f;
        CellSurface cell = new CellBuilder(CellId).Physics(new(0, 0, 0), new(2, 0, rise), new(2, 2, rise), new(0, 2, 0)).Build();
        cell.SampleFloorZ(1, 1)!.Value.Should().BeApproximately(rise / 2, 1e-4f);
    }

    [Fact]
    public void SampleFloorZ_StackedFloors_TopmostWithoutReferenceNearestWithOne()
    {
        CellSurface cell = new CellBuilder(CellId).Floor(-5, -5, 5, 5, 10).Floor(-5, -5, 5, 5, 13).Build();

        cell.SampleFloorZ(0, 0).Should().Be(13f, "without a reference the topmost floor wins");
        cell.SampleFloorZ(0, 0, 10.2f).Should().Be(10f);
        cell.SampleFloorZ(0, 0, 12f).Should().Be(13f);
        cell.SampleFloorZ(0, 0, 11.5f).Should().Be(13f, "an exact tie goes to the higher floor");
        cell.SampleFloorZ(0, 0, -100f).Should().Be(10f);
    }

    [Fact]
    public void SampleFloorZ_PolygonOrder_DoesNotChangeAnswers()
    {
        var random = new Random(3);
        var polygons = new List<Vector3[]>();
        for (int i = 0; i < 12; i++)
        {
            float x = random.Next(-10, 10), y = random.Next(-10, 10), z = random.Next(0, 6);
            polygons.Add(Square(x, y, x + random.Next(1, 8), y + random.Next(1, 8), z));
        }

        CellSurface forward = Build(polygons), backward = Build(Enumerable.Reverse(polygons));
        for (int n = 0; n < 2000; n++)
        {
            float x = (float)((random.NextDouble() * 24) - 12), y = (float)((random.NextDouble() * 24) - 12), r = (float)(random.NextDouble() * 8);
            backward.SampleFloorZ(x, y).Should().Be(forward.SampleFloorZ(x, y), $"topmost at ({x}, {y})");
            backward.SampleFloorZ(x, y, r).Should().Be(forward.SampleFloorZ(x, y, r), $"nearest to {r} at ({x}, {y})");
        }

        static CellSurface Build(IEnumerable<Vector3[]> polygons)
        {
            var builder = new CellBuilder(CellId);
            foreach (Vector3[] polygon in polygons)
            {
                builder.Physics(polygon);
            }

            return builder.Build();
        }
    }

    [Fact]
    public void SampleFloorZ_SharedDiagonalAndCentreVertex_AlwaysFindFloor()
    {
        // Four sloped triangles around a shared centre vertex: every point of every shared edge is on the floor.
        Vector3 centre = new(0.3f, 0.7f, 1.1f);
        Vector3[] corners = [new(-5, -5, 1), new(5, -5, 1.5f), new(5, 5, 0.5f), new(-5, 5, 2)];
        var builder = new CellBuilder(CellId);
        for (int i = 0; i < 4; i++)
        {
            builder.Physics(centre, corners[i], corners[(i + 1) % 4]);
        }

        CellSurface cell = builder.Build();
        cell.SampleFloorZ(centre.X, centre.Y)!.Value.Should().BeApproximately(centre.Z, 1e-5f);
        for (int i = 0; i < 4; i++)
        {
            for (float t = 0f; t <= 1f; t += 1f / 64)
            {
                Vector3 p = Vector3.Lerp(centre, corners[i], t);
                float? z = cell.SampleFloorZ(p.X, p.Y);
                z.Should().NotBeNull($"point {t} of the way along shared edge {i}");
                z!.Value.Should().BeApproximately(p.Z, 1e-4f, $"shared edge {i} at t {t}");
            }
        }
    }

    [Theory]
    [InlineData(180f)]
    [InlineData(90f)]
    [InlineData(-37.5f)]
    public void SampleFloorZ_RotatedCell_FloorLandsWhereTheFrameMovesIt(float degrees)
    {
        // A 2 × 6 m floor at cell-local x 1..3, y 0..6, z 0.5, placed at (100, 50, 20).
        var origin = new Vector3(100, 50, 20);
        var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, degrees * MathF.PI / 180f);
        CellSurface cell = new CellBuilder(CellId, origin, rotation).Floor(1, 0, 3, 6, 0.5f).Build();

        Vector3 inside = origin + Vector3.Transform(new Vector3(2, 3, 0), rotation);
        Vector3 outside = origin + Vector3.Transform(new Vector3(-2, 3, 0), rotation);
        cell.SampleFloorZ(inside.X, inside.Y)!.Value.Should().BeApproximately(20.5f, 1e-4f, $"rotated {degrees}°");
        cell.SampleFloorZ(outside.X, outside.Y).Should().BeNull($"cell-local (-2, 3) is off the floor, rotated {degrees}°");
        cell.Origin.Should().Be(origin);
    }

    [Fact]
    public void SampleFloorZ_SlightlyNonUnitQuaternion_IsNormalised()
    {
        var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI) * 1.001f;
        CellSurface cell = new CellBuilder(CellId, new Vector3(100, 50, 20), rotation).Floor(1, 0, 3, 6, 0.5f).Build();
        cell.SampleFloorZ(98, 47)!.Value.Should().BeApproximately(20.5f, 1e-5f, "a scaled quaternion must not scale the cell");
        cell.SampleFloorZ(97.05f, 44.05f).Should().NotBeNull("the far corner (cell-local (2.95, 5.95)) stays inside");
        cell.SampleFloorZ(96.9f, 43.9f).Should().BeNull("beyond the far corner");
    }

    [Fact]
    public void Portals_TargetFullIdsAndOutdoors_WithLandblockLocalGeometryPointingOut()
    {
        // A 4 × 4 room (cell-local 0..4) with a doorway to cell 0x0101 on its east wall and one to the
        // outdoors on its west wall, placed at (50, 60, 10) rotated 180°.
        var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI);
        var inside = new Vector3(2, 2, 1);
        CellSurface cell = new CellBuilder(CellId, new Vector3(50, 60, 10), rotation)
            .Floor(0, 0, 4, 4, 0)
            .Portal(0x0101, inside, Wall(4, 1, 4, 3, 0, 2))
            .Portal(0xFFFF, inside, Wall(0, 3, 0, 1, 0, 2))
            .Build();

        cell.Portals.Should().HaveCount(2);
        cell.Portals[0].TargetCellId.Should().Be(0xA9B40101u);
        cell.Portals[1].TargetCellId.Should().Be(0xA9B4FFFFu, "a portal to the outdoors targets the landblock id");

        // Cell-local (4, 2, 1) → landblock-local (46, 58, 11); out of the cell is cell-local +X → −X.
        cell.Portals[0].PortalOrigin.X.Should().BeApproximately(46f, 1e-4f);
        cell.Portals[0].PortalOrigin.Y.Should().BeApproximately(58f, 1e-4f);
        cell.Portals[0].PortalOrigin.Z.Should().BeApproximately(11f, 1e-4f);
        cell.Portals[0].PortalNormal.X.Should().BeApproximately(-1f, 1e-5f);
        cell.Portals[1].PortalNormal.X.Should().BeApproximately(1f, 1e-5f);
        cell.Portals[1].PortalNormal.Length().Should().BeApproximately(1f, 1e-5f);
    }
}
