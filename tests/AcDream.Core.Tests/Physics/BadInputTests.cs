using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Physics;

/// <summary>Bad input gets an ArgumentException naming the argument, the id and what is wrong.</summary>
public class BadInputTests
{
    private const uint CellId = 0xA9B40100u;

    [Fact]
    public void TerrainSurface_WrongLengthsAndNonFiniteHeights_Throw()
    {
        FluentActions.Invoking(() => new TerrainSurface(new byte[80], LinearTable(), Holtburg))
            .Should().Throw<ArgumentException>().WithParameterName("heights").WithMessage("*0xA9B4FFFF*81*80*");
        FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), new float[255]))
            .Should().Throw<ArgumentException>().WithParameterName("heightTable").WithMessage("*256*255*");
        float[] table = LinearTable();
        table[17] = float.NaN;
        FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), table, Holtburg))
            .Should().Throw<ArgumentException>().WithParameterName("heightTable").WithMessage("*heightTable[17]*finite*");
        FluentActions.Invoking(() => new TerrainSurface(null!, LinearTable())).Should().Throw<ArgumentNullException>().WithParameterName("heights");
        FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), null!)).Should().Throw<ArgumentNullException>().WithParameterName("heightTable");
        FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), LinearTable(), 0xA9B40143u))
            .Should().Throw<ArgumentException>().WithParameterName("landblockId").WithMessage("*0xA9B40143*low 16 bits*");
        FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), LinearTable(), 0xFF00FFFFu))
            .Should().Throw<ArgumentException>().WithParameterName("landblockId").WithMessage("*0xFF00FFFF*");
    }

    [Theory]
    [InlineData(float.NaN, 1f, "localX")]
    [InlineData(1f, float.PositiveInfinity, "localY")]
    public void TerrainSurface_NonFiniteQuery_Throws(float x, float y, string name)
    {
        TerrainSurface terrain = FlatTerrain(1f);
        FluentActions.Invoking(() => terrain.SampleZ(x, y)).Should().Throw<ArgumentException>().WithParameterName(name);
        FluentActions.Invoking(() => terrain.ComputeOutdoorCellId(x, y)).Should().Throw<ArgumentException>().WithParameterName(name);
    }

    [Fact]
    public void CellSurface_BadIdsAndArguments_Throw()
    {
        var good = new CellBuilder(CellId).Floor(0, 0, 1, 1, 0);
        FluentActions.Invoking(() => new CellSurface(0xA9B40040u, good.EnvCell, good.CellStruct))
            .Should().Throw<ArgumentException>().WithParameterName("cellId").WithMessage("*0xA9B40040*indoor*");
        FluentActions.Invoking(() => new CellSurface(0xA9B40101u, good.EnvCell, good.CellStruct))
            .Should().Throw<ArgumentException>().WithParameterName("envCell").WithMessage("*0xA9B40101*0xA9B40100*");
        FluentActions.Invoking(() => new CellSurface(CellId, null!, good.CellStruct)).Should().Throw<ArgumentNullException>().WithParameterName("envCell");
        FluentActions.Invoking(() => new CellSurface(CellId, good.EnvCell, null!)).Should().Throw<ArgumentNullException>().WithParameterName("cellStruct");
    }

    [Fact]
    public void CellSurface_BadGeometry_ThrowsNamingCellAndPolygon()
    {
        var twoVertices = new CellBuilder(CellId);
        twoVertices.CellStruct.VertexArray.Vertices[0] = new SWVertex { Origin = Vector3.Zero };
        twoVertices.CellStruct.VertexArray.Vertices[1] = new SWVertex { Origin = Vector3.UnitX };
        twoVertices.CellStruct.PhysicsPolygons[7] = new Polygon { VertexIds = [0, 1] };
        FluentActions.Invoking(twoVertices.Build).Should().Throw<ArgumentException>().WithParameterName("cellStruct")
            .WithMessage("*0xA9B40100*physics polygon 7*2 vertices*");

        var unknownVertex = new CellBuilder(CellId).Floor(0, 0, 1, 1, 0);
        unknownVertex.CellStruct.PhysicsPolygons[0].VertexIds[2] = 99;
        FluentActions.Invoking(unknownVertex.Build).Should().Throw<ArgumentException>().WithMessage("*0xA9B40100*physics polygon 0*vertex 99*");

        var nanVertex = new CellBuilder(CellId).Floor(0, 0, 1, 1, 0);
        nanVertex.CellStruct.VertexArray.Vertices[1].Origin = new Vector3(float.NaN, 0, 0);
        FluentActions.Invoking(nanVertex.Build).Should().Throw<ArgumentException>().WithMessage("*0xA9B40100*vertex 1*finite*");

        var missingPortal = new CellBuilder(CellId).Floor(0, 0, 1, 1, 0);
        missingPortal.EnvCell.CellPortals.Add(new CellPortal { OtherCellId = 0x0101, PolygonId = 42 });
        FluentActions.Invoking(missingPortal.Build).Should().Throw<ArgumentException>()
            .WithMessage("*0xA9B40100*portal 0*0x0101*polygon 42*lacks*");

        var badOrigin = new CellBuilder(CellId, new Vector3(float.PositiveInfinity, 0, 0)).Floor(0, 0, 1, 1, 0);
        FluentActions.Invoking(badOrigin.Build).Should().Throw<ArgumentException>().WithParameterName("envCell").WithMessage("*0xA9B40100*Origin*");

        var zeroRotation = new CellBuilder(CellId, Vector3.Zero, new Quaternion(0, 0, 0, 0)).Floor(0, 0, 1, 1, 0);
        FluentActions.Invoking(zeroRotation.Build).Should().Throw<ArgumentException>().WithParameterName("envCell").WithMessage("*0xA9B40100*Orientation*");
    }

    [Fact]
    public void CellSurface_NonFiniteQuery_Throws()
    {
        CellSurface cell = new CellBuilder(CellId).Floor(0, 0, 1, 1, 0).Build();
        FluentActions.Invoking(() => cell.SampleFloorZ(float.NaN, 0)).Should().Throw<ArgumentException>().WithParameterName("worldX");
        FluentActions.Invoking(() => cell.SampleFloorZ(0, 0, float.NegativeInfinity)).Should().Throw<ArgumentException>().WithParameterName("referenceZ");
    }

    [Fact]
    public void AddLandblock_BadArguments_ThrowAndLeaveEngineUnchanged()
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(10f), []);
        ResolveResult before = engine.Resolve(new Vector3(5, 5, 10), 0, new Vector3(1, 0, 0), 0.5f);

        CellSurface foreign = new CellBuilder(0xAAB40100u).Floor(0, 0, 1, 1, 0).Build();
        CellSurface mine = new CellBuilder(CellId).Floor(0, 0, 10, 10, 10.2f).Build();
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, FlatTerrain(20f), [mine, foreign]))
            .Should().Throw<ArgumentException>().WithParameterName("cells").WithMessage("*0xA9B4FFFF*0xAAB40100*another landblock*");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, FlatTerrain(20f), [mine, mine]))
            .Should().Throw<ArgumentException>().WithParameterName("cells").WithMessage("*0xA9B40100*twice*");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, FlatTerrain(20f, 0xAAB4FFFFu), []))
            .Should().Throw<ArgumentException>().WithParameterName("terrain").WithMessage("*0xA9B4FFFF*0xAAB4FFFF*");
        FluentActions.Invoking(() => engine.AddLandblock(0xA9B40100u, FlatTerrain(20f), []))
            .Should().Throw<ArgumentException>().WithParameterName("landblockId");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, null!, [])).Should().Throw<ArgumentNullException>().WithParameterName("terrain");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, FlatTerrain(20f), null!)).Should().Throw<ArgumentNullException>().WithParameterName("cells");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, FlatTerrain(20f), [null!])).Should().Throw<ArgumentNullException>().WithParameterName("cells");

        engine.LandblockCount.Should().Be(1);
        engine.Resolve(new Vector3(5, 5, 10), 0, new Vector3(1, 0, 0), 0.5f).Should().Be(before, "a rejected AddLandblock changes nothing");
    }

    [Fact]
    public void Resolve_BadArguments_ThrowAndLeaveEngineUnchanged()
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(10f), [new CellBuilder(CellId).Floor(50, 50, 60, 60, 10.2f).Build()]);
        var pos = new Vector3(5, 5, 10);
        ResolveResult before = engine.Resolve(pos, 0, new Vector3(1, 0, 0), 0.5f);

        FluentActions.Invoking(() => engine.Resolve(new Vector3(float.NaN, 5, 10), 0, Vector3.Zero, 0.5f))
            .Should().Throw<ArgumentException>().WithParameterName("currentPos");
        FluentActions.Invoking(() => engine.Resolve(pos, 0, new Vector3(0, 0, float.PositiveInfinity), 0.5f))
            .Should().Throw<ArgumentException>().WithParameterName("delta");
        FluentActions.Invoking(() => engine.Resolve(pos, 0, Vector3.Zero, float.NaN))
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("stepUpHeight");
        FluentActions.Invoking(() => engine.Resolve(pos, 0, Vector3.Zero, -0.1f))
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("stepUpHeight");
        FluentActions.Invoking(() => engine.Resolve(pos, 0xA9B40041u, Vector3.Zero, 0.5f))
            .Should().Throw<ArgumentException>().WithParameterName("currentCellId").WithMessage("*0xA9B40041*");
        FluentActions.Invoking(() => engine.Resolve(pos, 0xA9B4FFFEu, Vector3.Zero, 0.5f))
            .Should().Throw<ArgumentException>().WithParameterName("currentCellId");
        FluentActions.Invoking(() => engine.Resolve(pos, 0xA9B40123u, Vector3.Zero, 0.5f))
            .Should().Throw<ArgumentException>().WithParameterName("currentCellId").WithMessage("*0xA9B40123*not registered*");
        FluentActions.Invoking(() => new PhysicsEngine(0xA9B40001u))
            .Should().Throw<ArgumentException>().WithParameterName("centerLandblockId");

        engine.Resolve(pos, 0, new Vector3(1, 0, 0), 0.5f).Should().Be(before);
    }
}
