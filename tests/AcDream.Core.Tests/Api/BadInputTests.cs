using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// Bad input gets an ArgumentException naming the argument, the id and what is wrong, and changes nothing:
/// NaN and infinity in every float argument of every public method, wrong lengths, unknown ids, bad option
/// and body values. Huge finite inputs: finite answers.
/// </summary>
public class BadInputTests
{
    private const uint Room = 0xA9B40100u;

    private static readonly float[] NonFinite = [float.NaN, float.PositiveInfinity, float.NegativeInfinity];

    private static PhysicsEngine Engine(PhysicsEngine? engine = null)
    {
        engine ??= new PhysicsEngine(Holtburg);
        CellSurface room = new CellBuilder(Room).Floor(20, 20, 24, 24, 50.2f)
            .Portal(0xFFFF, new Vector3(22, 22, 51), Wall(20, 23, 20, 21, 50.2f, 52.7f)).Build();
        engine.AddLandblock(Holtburg, new TerrainSurface(Heights((x, y) => 20 + x + y), LinearTable(), Holtburg), [room]);
        return engine;
    }

    /// <summary>A fixed battery of resolves whose answers must not change.</summary>
    private static ResolveResult[] Probe(PhysicsEngine engine) =>
    [
        engine.Resolve(new Vector3(19.8f, 22, 50), 0xA9B40000u, new Vector3(0.5f, 0, 0), 0.5f),
        engine.Resolve(new Vector3(22, 22, 50.2f), Room, new Vector3(-2.5f, 0, 0), 0.5f),
        engine.Resolve(new Vector3(100, 100, 0), 0, new Vector3(1, 1, 0), 100f),
        engine.Resolve(new Vector3(191.5f, 3, 0), 0xA9B40039u, new Vector3(1, 0, 0), 100f),
    ];

    [Fact]
    public void Resolve_NaNOrInfinityInEveryComponent_ThrowsNamingItAndEngineUnchanged()
    {
        PhysicsEngine engine = Engine();
        ResolveResult[] before = Probe(engine);
        var pos = new Vector3(22, 22, 50.2f);
        int cases = 0;
        foreach (float bad in NonFinite)
        {
            for (int component = 0; component < 3; component++)
            {
                Vector3 badVector = pos;
                badVector[component] = bad;
                foreach (uint cell in new[] { 0xA9B40000u, Room })
                {
                    FluentActions.Invoking(() => engine.Resolve(badVector, cell, Vector3.Zero, 0.5f))
                        .Should().Throw<ArgumentException>($"currentPos[{component}] = {bad}").WithParameterName("currentPos");
                    FluentActions.Invoking(() => engine.Resolve(pos, cell, badVector - pos + new Vector3(0, 0, 0), 0.5f))
                        .Should().Throw<ArgumentException>($"delta[{component}] = {bad}").WithParameterName("delta");
                    FluentActions.Invoking(() => engine.Resolve(badVector, cell, Vector3.Zero, 0.5f, MovementOptions.Player))
                        .Should().Throw<ArgumentException>($"options overload, currentPos[{component}] = {bad}").WithParameterName("currentPos");
                    cases += 3;
                }
            }

            foreach (uint cell in new[] { 0xA9B40000u, Room })
            {
                FluentActions.Invoking(() => engine.Resolve(pos, cell, Vector3.Zero, bad))
                    .Should().Throw<ArgumentOutOfRangeException>($"stepUpHeight = {bad}").WithParameterName("stepUpHeight");
                FluentActions.Invoking(() => engine.Resolve(pos, cell, Vector3.Zero, bad, default))
                    .Should().Throw<ArgumentOutOfRangeException>($"options overload, stepUpHeight = {bad}").WithParameterName("stepUpHeight");
                cases += 2;
            }

            FluentActions.Invoking(() => new MovementOptions { StepDownHeight = bad }).Should().Throw<ArgumentOutOfRangeException>().WithParameterName("StepDownHeight");
            FluentActions.Invoking(() => new MovementOptions { SweepStepLength = bad }).Should().Throw<ArgumentOutOfRangeException>().WithParameterName("SweepStepLength");
        }

        cases.Should().Be(66);
        Probe(engine).Should().Equal(before, "a rejected call changes nothing");
    }

    [Theory]
    [InlineData(0xA9B40041u, "currentCellId")]   // between outdoor and indoor numbers
    [InlineData(0xA9B400FFu, "currentCellId")]
    [InlineData(0xA9B4FFFEu, "currentCellId")]   // the object list
    [InlineData(0xA9B4FFFFu, "currentCellId")]   // the landblock itself
    [InlineData(0xA9B40123u, "currentCellId")]   // an indoor cell the registered landblock lacks
    [InlineData(0xFFB40001u, "currentCellId")]   // a landblock X off the world
    [InlineData(0xA9FF0100u, "currentCellId")]   // a landblock Y off the world
    [InlineData(0xFFFF0000u, "currentCellId")]
    public void Resolve_UnknownOrInvalidCellId_ThrowsAndEngineUnchanged(uint cellId, string parameter)
    {
        PhysicsEngine engine = Engine();
        ResolveResult[] before = Probe(engine);
        FluentActions.Invoking(() => engine.Resolve(new Vector3(22, 22, 50.2f), cellId, Vector3.Zero, 0.5f))
            .Should().Throw<ArgumentException>().WithParameterName(parameter).WithMessage($"*0x{cellId:X8}*");
        Probe(engine).Should().Equal(before);
    }

    [Fact]
    public void Resolve_BadArguments_ThrowAndLeaveEngineUnchanged()
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(10f), [new CellBuilder(Room).Floor(50, 50, 60, 60, 10.2f).Build()]);
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
        FluentActions.Invoking(() => engine.Resolve(new MoveRequest(pos, 0, Vector3.Zero, -0.1f) { Options = MovementOptions.Player, WithReport = true }))
            .Should().Throw<ArgumentOutOfRangeException>("the request is checked as the spec's call").WithParameterName("request").WithMessage("*request.StepUpHeight*");
        FluentActions.Invoking(() => engine.Resolve(new MoveRequest(new Vector3(5, float.NaN, 10), 0, Vector3.Zero, 0.5f)))
            .Should().Throw<ArgumentException>().WithParameterName("request").WithMessage("*request.Position*");
        FluentActions.Invoking(() => engine.Resolve(new MoveRequest(pos, 0, new Vector3(float.NegativeInfinity, 0, 0), 0.5f)))
            .Should().Throw<ArgumentException>().WithParameterName("request").WithMessage("*request.Delta*");
        FluentActions.Invoking(() => engine.Resolve(new MoveRequest(pos, 0xA9B40041u, Vector3.Zero, 0.5f)))
            .Should().Throw<ArgumentException>().WithParameterName("request").WithMessage("*request.CellId 0xA9B40041*");
        FluentActions.Invoking(() => engine.TryGetGround(pos, 0, -0.1f, out _, out _, out _))
            .Should().Throw<ArgumentOutOfRangeException>("the ground query's step is checked as Resolve's").WithParameterName("stepUpHeight");
        FluentActions.Invoking(() => engine.TryGetGround(pos, 0, float.NaN, out _, out _, out _))
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

    [Fact]
    public void Resolve_HugeFiniteInputs_FiniteAnswersNeverNaN()
    {
        PhysicsEngine engine = Engine(new PhysicsEngine());
        Vector3 offset = engine.GetLandblockOrigin(Holtburg);
        float[] values = [0f, -0f, 1e-45f, 1e-20f, 1f, -1f, 5e3f, -5e3f, 1e7f, -1e7f, 1e20f, -1e20f, 1e38f, -1e38f, float.MaxValue, -float.MaxValue];
        var random = new Random(41);
        for (int n = 0; n < 20_000; n++)
        {
            Vector3 Pick(bool nearRoom) => nearRoom && random.Next(2) == 0
                ? offset + new Vector3(Gen.Range(random, 19, 25), Gen.Range(random, 19, 25), 50.2f)
                : new Vector3(values[random.Next(values.Length)], values[random.Next(values.Length)], values[random.Next(values.Length)]);
            Vector3 pos = Pick(true), delta = Pick(false);
            float step = MathF.Abs(values[random.Next(values.Length)]);
            uint cell = random.Next(3) switch { 0 => Room, 1 => 0xA9B40000u, _ => 0u };
            ResolveResult r = engine.Resolve(pos, cell, delta, step);
            string what = $"case {n}: {pos:R} in 0x{cell:X8} by {delta:R}, step {step:R} → {r}";
            (float.IsFinite(r.Position.X) && float.IsFinite(r.Position.Y) && float.IsFinite(r.Position.Z)).Should().BeTrue(what);
            uint low = r.CellId & 0xFFFF;
            (low is >= 1 and <= 0x40 || low == (Room & 0xFFFF)).Should().BeTrue($"a real cell id: {what}");
            (r.CellId >> 24).Should().BeLessThanOrEqualTo(0xFEu, $"a landblock of the world: {what}");
            ((r.CellId >> 16) & 0xFF).Should().BeLessThanOrEqualTo(0xFEu, $"a landblock of the world: {what}");
        }
    }

    [Fact]
    public void SurfaceQueries_NaNOrInfinityInEveryArgument_ThrowNamingItAndAnswersUnchanged()
    {
        var terrain = new TerrainSurface(Heights((x, y) => x + y), LinearTable(), Holtburg);
        CellSurface cell = new CellBuilder(Room).Floor(0, 0, 4, 4, 1).Build();
        (float, uint, float?, float?) Answers() => (terrain.SampleZ(30, 40), terrain.ComputeOutdoorCellId(30, 40), cell.SampleFloorZ(2, 2), cell.SampleFloorZ(2, 2, 0));
        var before = Answers();
        foreach (float bad in NonFinite)
        {
            FluentActions.Invoking(() => terrain.SampleZ(bad, 1)).Should().Throw<ArgumentException>().WithParameterName("localX");
            FluentActions.Invoking(() => terrain.SampleZ(1, bad)).Should().Throw<ArgumentException>().WithParameterName("localY");
            FluentActions.Invoking(() => terrain.ComputeOutdoorCellId(bad, 1)).Should().Throw<ArgumentException>().WithParameterName("localX");
            FluentActions.Invoking(() => terrain.ComputeOutdoorCellId(1, bad)).Should().Throw<ArgumentException>().WithParameterName("localY");
            FluentActions.Invoking(() => cell.SampleFloorZ(bad, 1)).Should().Throw<ArgumentException>().WithParameterName("worldX");
            FluentActions.Invoking(() => cell.SampleFloorZ(1, bad)).Should().Throw<ArgumentException>().WithParameterName("worldY");
            FluentActions.Invoking(() => cell.SampleFloorZ(bad, 1, 0)).Should().Throw<ArgumentException>().WithParameterName("worldX");
            FluentActions.Invoking(() => cell.SampleFloorZ(1, bad, 0)).Should().Throw<ArgumentException>().WithParameterName("worldY");
            FluentActions.Invoking(() => cell.SampleFloorZ(1, 1, bad)).Should().Throw<ArgumentException>().WithParameterName("referenceZ");
        }

        Answers().Should().Be(before);

        // Huge finite queries clamp (terrain) or find no floor (cells): never NaN.
        foreach (float big in new[] { float.MaxValue, -float.MaxValue, 1e30f, -1e30f })
        {
            float.IsFinite(terrain.SampleZ(big, -big)).Should().BeTrue($"{big}");
            terrain.ComputeOutdoorCellId(big, big).Should().BeInRange(1u, 0x40u);
            cell.SampleFloorZ(big, 2).Should().BeNull($"{big} is far off the floor");
            cell.SampleFloorZ(2, 2, big).Should().Be(1f);
        }
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
    public void CellSurface_NonFiniteQuery_Throws()
    {
        CellSurface cell = new CellBuilder(Room).Floor(0, 0, 1, 1, 0).Build();
        FluentActions.Invoking(() => cell.SampleFloorZ(float.NaN, 0)).Should().Throw<ArgumentException>().WithParameterName("worldX");
        FluentActions.Invoking(() => cell.SampleFloorZ(0, 0, float.NegativeInfinity)).Should().Throw<ArgumentException>().WithParameterName("referenceZ");
    }

    [Fact]
    public void TerrainSurface_BadArrays_ThrowNamingTheArgument()
    {
        foreach (int length in new[] { 0, 1, 80, 82, 256 })
        {
            FluentActions.Invoking(() => new TerrainSurface(new byte[length], LinearTable())).Should().Throw<ArgumentException>().WithParameterName("heights").WithMessage($"*{length}*");
            FluentActions.Invoking(() => new TerrainSurface(new byte[length], LinearTable(), Holtburg)).Should().Throw<ArgumentException>().WithParameterName("heights");
        }

        foreach (int length in new[] { 0, 81, 255, 257 })
        {
            FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), new float[length], Holtburg)).Should().Throw<ArgumentException>().WithParameterName("heightTable").WithMessage($"*{length}*");
        }

        foreach (float bad in NonFinite)
        {
            foreach (int index in new[] { 0, 128, 255 })
            {
                float[] table = LinearTable();
                table[index] = bad;
                FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), table)).Should().Throw<ArgumentException>().WithParameterName("heightTable").WithMessage($"*heightTable[{index}]*");
            }
        }

        foreach (uint id in new[] { 0xA9B40001u, 0xA9B4FFFEu, 0xFF00FFFFu, 0x00FFFFFFu, 0xFFFFFFFFu })
        {
            FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), LinearTable(), id)).Should().Throw<ArgumentException>().WithParameterName("landblockId").WithMessage($"*0x{id:X8}*");
        }
    }

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

    [Fact]
    public void CellSurface_NaNOrInfinityInOriginOrientationOrVertex_ThrowsNamingTheCell()
    {
        foreach (float bad in NonFinite)
        {
            for (int c = 0; c < 4; c++)
            {
                if (c < 3)
                {
                    Vector3 origin = new(1, 2, 3);
                    origin[c] = bad;
                    var badOrigin = new CellBuilder(Room, origin).Floor(0, 0, 1, 1, 0);
                    FluentActions.Invoking(badOrigin.Build).Should().Throw<ArgumentException>().WithParameterName("envCell").WithMessage("*0xA9B40100*Origin*");

                    var badVertex = new CellBuilder(Room).Floor(0, 0, 1, 1, 0);
                    Vector3 v = badVertex.CellStruct.VertexArray.Vertices[2].Origin;
                    v[c] = bad;
                    badVertex.CellStruct.VertexArray.Vertices[2].Origin = v;
                    FluentActions.Invoking(badVertex.Build).Should().Throw<ArgumentException>().WithParameterName("cellStruct").WithMessage("*0xA9B40100*vertex 2*finite*");
                }

                Quaternion q = Quaternion.Identity;
                q[c] = bad;
                var badRotation = new CellBuilder(Room, Vector3.Zero, q).Floor(0, 0, 1, 1, 0);
                FluentActions.Invoking(badRotation.Build).Should().Throw<ArgumentException>().WithParameterName("envCell").WithMessage("*0xA9B40100*Orientation*");
            }
        }

        // Finite inputs whose placement overflows, or lands absurdly far away: rejected, not NaN later.
        var overflow = new CellBuilder(Room, new Vector3(3e38f, 0, 0)).Floor(0, 0, 3e38f, 1, 0);
        FluentActions.Invoking(overflow.Build).Should().Throw<ArgumentException>().WithParameterName("cellStruct").WithMessage("*0xA9B40100*vertex*placed*");
        var far = new CellBuilder(Room, new Vector3(0, 2e5f, 0)).Floor(0, 0, 1, 1, 0);
        FluentActions.Invoking(far.Build).Should().Throw<ArgumentException>().WithMessage("*0xA9B40100*100000 m*");
        var tiny = new CellBuilder(Room, Vector3.Zero, new Quaternion(0, 0, 0, 1e-7f)).Floor(0, 0, 1, 1, 0);
        FluentActions.Invoking(tiny.Build).Should().Throw<ArgumentException>().WithParameterName("envCell").WithMessage("*Orientation*");
    }

    [Fact]
    public void CellSurface_NullsWrongCountsAndUnknownIds_ThrowNamingTheCell()
    {
        static CellBuilder Good() => new CellBuilder(Room).Floor(0, 0, 1, 1, 0);
        var cases = new (string What, Action<CellBuilder> Break, string Message)[]
        {
            ("null Position", b => b.EnvCell.Position = null!, "*Position*"),
            ("null CellPortals", b => b.EnvCell.CellPortals = null!, "*CellPortals*"),
            ("null PhysicsPolygons", b => b.CellStruct.PhysicsPolygons = null!, "*PhysicsPolygons*"),
            ("null Polygons", b => b.CellStruct.Polygons = null!, "*Polygons*"),
            ("null VertexArray", b => b.CellStruct.VertexArray = null!, "*VertexArray*"),
            ("null polygon", b => b.CellStruct.PhysicsPolygons[9] = null!, "*physics polygon 9*"),
            ("two vertices", b => b.CellStruct.PhysicsPolygons[0].VertexIds.RemoveRange(2, 2), "*physics polygon 0*2 vertices*"),
            ("unknown vertex", b => b.CellStruct.PhysicsPolygons[0].VertexIds[1] = 77, "*vertex 77*"),
            ("negative vertex id", b => b.CellStruct.PhysicsPolygons[0].VertexIds[1] = -3, "*vertex -3*"),
            ("null portal", b => b.EnvCell.CellPortals.Add(null!), "*CellPortals[0]*"),
            ("portal to a missing polygon", b => b.EnvCell.CellPortals.Add(new CellPortal { OtherCellId = 0x0101, PolygonId = 5 }), "*portal 0*polygon 5*"),
        };
        foreach ((string what, Action<CellBuilder> breakIt, string message) in cases)
        {
            CellBuilder builder = Good();
            breakIt(builder);
            FluentActions.Invoking(builder.Build).Should().Throw<ArgumentException>(what).WithMessage($"*0xA9B40100*{message}");
        }
    }

    [Fact]
    public void CellSurface_BadIdsAndArguments_Throw()
    {
        var good = new CellBuilder(Room).Floor(0, 0, 1, 1, 0);
        FluentActions.Invoking(() => new CellSurface(0xA9B40040u, good.EnvCell, good.CellStruct))
            .Should().Throw<ArgumentException>().WithParameterName("cellId").WithMessage("*0xA9B40040*indoor*");
        FluentActions.Invoking(() => new CellSurface(0xA9B40101u, good.EnvCell, good.CellStruct))
            .Should().Throw<ArgumentException>().WithParameterName("envCell").WithMessage("*0xA9B40101*0xA9B40100*");
        FluentActions.Invoking(() => new CellSurface(Room, null!, good.CellStruct)).Should().Throw<ArgumentNullException>().WithParameterName("envCell");
        FluentActions.Invoking(() => new CellSurface(Room, good.EnvCell, null!)).Should().Throw<ArgumentNullException>().WithParameterName("cellStruct");
    }

    [Fact]
    public void CellSurface_BadGeometry_ThrowsNamingCellAndPolygon()
    {
        var twoVertices = new CellBuilder(Room);
        twoVertices.CellStruct.VertexArray.Vertices[0] = new SWVertex { Origin = Vector3.Zero };
        twoVertices.CellStruct.VertexArray.Vertices[1] = new SWVertex { Origin = Vector3.UnitX };
        twoVertices.CellStruct.PhysicsPolygons[7] = new Polygon { VertexIds = [0, 1] };
        FluentActions.Invoking(twoVertices.Build).Should().Throw<ArgumentException>().WithParameterName("cellStruct")
            .WithMessage("*0xA9B40100*physics polygon 7*2 vertices*");

        var unknownVertex = new CellBuilder(Room).Floor(0, 0, 1, 1, 0);
        unknownVertex.CellStruct.PhysicsPolygons[0].VertexIds[2] = 99;
        FluentActions.Invoking(unknownVertex.Build).Should().Throw<ArgumentException>().WithMessage("*0xA9B40100*physics polygon 0*vertex 99*");

        var nanVertex = new CellBuilder(Room).Floor(0, 0, 1, 1, 0);
        nanVertex.CellStruct.VertexArray.Vertices[1].Origin = new Vector3(float.NaN, 0, 0);
        FluentActions.Invoking(nanVertex.Build).Should().Throw<ArgumentException>().WithMessage("*0xA9B40100*vertex 1*finite*");

        var missingPortal = new CellBuilder(Room).Floor(0, 0, 1, 1, 0);
        missingPortal.EnvCell.CellPortals.Add(new CellPortal { OtherCellId = 0x0101, PolygonId = 42 });
        FluentActions.Invoking(missingPortal.Build).Should().Throw<ArgumentException>()
            .WithMessage("*0xA9B40100*portal 0*0x0101*polygon 42*lacks*");

        var badOrigin = new CellBuilder(Room, new Vector3(float.PositiveInfinity, 0, 0)).Floor(0, 0, 1, 1, 0);
        FluentActions.Invoking(badOrigin.Build).Should().Throw<ArgumentException>().WithParameterName("envCell").WithMessage("*0xA9B40100*Origin*");

        var zeroRotation = new CellBuilder(Room, Vector3.Zero, new Quaternion(0, 0, 0, 0)).Floor(0, 0, 1, 1, 0);
        FluentActions.Invoking(zeroRotation.Build).Should().Throw<ArgumentException>().WithParameterName("envCell").WithMessage("*0xA9B40100*Orientation*");
    }

    [Fact]
    public void AddLandblock_BadIdsAndCells_ThrowAndTheRegisteredLandblockStays()
    {
        PhysicsEngine engine = Engine();
        ResolveResult[] before = Probe(engine);
        TerrainSurface other = FlatTerrain(3f);
        foreach (uint id in new[] { 0xA9B40100u, 0xFFB4FFFFu, 0xA9FFFFFFu, 0xFFFFFFFFu })
        {
            FluentActions.Invoking(() => engine.AddLandblock(id, other, [])).Should().Throw<ArgumentException>().WithParameterName("landblockId").WithMessage($"*0x{id:X8}*");
        }

        CellSurface stranger = new CellBuilder(0xAAB40100u).Floor(0, 0, 1, 1, 0).Build();
        CellSurface mine = new CellBuilder(Room).Floor(0, 0, 1, 1, 0).Build();
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, other, [mine, stranger])).Should().Throw<ArgumentException>().WithParameterName("cells");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, other, [mine, mine])).Should().Throw<ArgumentException>().WithParameterName("cells");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, FlatTerrain(3f, 0xA9B3FFFFu), [])).Should().Throw<ArgumentException>().WithParameterName("terrain");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, null!, [])).Should().Throw<ArgumentNullException>().WithParameterName("terrain");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, other, null!)).Should().Throw<ArgumentNullException>().WithParameterName("cells");
        FluentActions.Invoking(() => engine.AddLandblock(Holtburg, other, [mine, null!])).Should().Throw<ArgumentNullException>().WithParameterName("cells");
        FluentActions.Invoking(() => new PhysicsEngine(0xFF00FFFFu)).Should().Throw<ArgumentException>().WithParameterName("centerLandblockId");

        // Unknown landblocks in the queries: documented no-ops, not errors (an unload path may call them unconditionally).
        engine.RemoveLandblock(0x0101FFFFu);
        engine.RemoveLandblock(0xFFFFFFFFu);
        engine.ContainsLandblock(0xFFFFFFFFu).Should().BeFalse();
        engine.LandblockCount.Should().Be(1);
        Probe(engine).Should().Equal(before, "the failed calls left the registered landblock as it was");
    }

    [Fact]
    public void AddLandblock_BadArguments_ThrowAndLeaveEngineUnchanged()
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(10f), []);
        ResolveResult before = engine.Resolve(new Vector3(5, 5, 10), 0, new Vector3(1, 0, 0), 0.5f);

        CellSurface foreign = new CellBuilder(0xAAB40100u).Floor(0, 0, 1, 1, 0).Build();
        CellSurface mine = new CellBuilder(Room).Floor(0, 0, 10, 10, 10.2f).Build();
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
    public void Options_InvalidValues_ThrowAtConstruction()
    {
        FluentActions.Invoking(() => new MovementOptions { StepDownHeight = -1f })
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("StepDownHeight");
        FluentActions.Invoking(() => new MovementOptions { StepDownHeight = float.NaN })
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("StepDownHeight");
        FluentActions.Invoking(() => new MovementOptions { SweepStepLength = 0f })
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("SweepStepLength");
        FluentActions.Invoking(() => new MovementOptions { SweepStepLength = float.PositiveInfinity })
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("SweepStepLength");
    }

    [Theory]
    [InlineData(-0.48f, 1.835f, "radius")]
    [InlineData(0f, 1.835f, "radius")]
    [InlineData(float.NaN, 1.835f, "radius")]
    [InlineData(float.PositiveInfinity, 1.835f, "radius")]
    [InlineData(float.NegativeInfinity, 1.835f, "radius")]
    [InlineData(0.48f, -1.835f, "height")]
    [InlineData(0.48f, 0f, "height")]
    [InlineData(0.48f, float.NaN, "height")]
    [InlineData(0.48f, float.PositiveInfinity, "height")]
    [InlineData(0.48f, float.NegativeInfinity, "height")]
    public void MoverBody_BadSize_ThrowsNamingIt(float radius, float height, string name)
    {
        FluentActions.Invoking(() => new MoverBody(radius, height))
            .Should().Throw<ArgumentException>().WithParameterName(name).Which.Message.Should().Contain("finite");
    }

    [Fact]
    public void MovementOptions_DefaultBody_ThrowsNamingBody()
    {
        // default(MoverBody) has a zero radius and height: as an option it is an error, not a point.
        FluentActions.Invoking(() => new MovementOptions { Body = default(MoverBody) })
            .Should().Throw<ArgumentException>().WithParameterName("Body").Which.Message.Should().Contain("default(MoverBody)");
        FluentActions.Invoking(() => new MovementOptions { Body = new MoverBody() })
            .Should().Throw<ArgumentException>().WithParameterName("Body");
        FluentActions.Invoking(() => MovementOptions.Player with { Body = default(MoverBody) })
            .Should().Throw<ArgumentException>().WithParameterName("Body");
    }

    [Fact]
    public void MovementOptions_GoodOrNoBody_Accepted()
    {
        new MovementOptions { Body = null }.Body.Should().BeNull();
        new MovementOptions { Body = new MoverBody(1e-6f, 1e-6f) }.Body.Should().Be(new MoverBody(1e-6f, 1e-6f));
        MovementOptions.Player.Body.Should().Be(new MoverBody(0.48f, 1.835f), "the player's body: radius 0.48 m, 1.835 m tall");
        (MovementOptions.Player with { Body = null }).Body.Should().BeNull();
    }
}
