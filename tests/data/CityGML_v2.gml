<?xml version="1.0" encoding="UTF-8"?>
<CityModel xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xmlns:xAL="urn:oasis:names:tc:ciq:xsdschema:xAL:2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:gml="http://www.opengis.net/gml" xmlns:gen="http://www.opengis.net/citygml/generics/2.0" xmlns="http://www.opengis.net/citygml/2.0" xsi:schemaLocation="http://www.opengis.net/citygml/2.0 http://schemas.opengis.net/citygml/2.0/cityGMLBase.xsd http://www.opengis.net/citygml/building/2.0 http://schemas.opengis.net/citygml/building/2.0/building.xsd http://www.opengis.net/citygml/generics/2.0 http://schemas.opengis.net/citygml/generics/2.0/generics.xsd">
    <gml:name>LoD2_4490_5322_1_BY</gml:name>
    <gml:boundedBy>
        <gml:Envelope srsName="urn:adv:crs:DE_DHDN_3GK4*DE_DHHN92_NH" srsDimension="3">
            <gml:lowerCorner>4490655.500 5322005.280 548.470</gml:lowerCorner>
            <gml:upperCorner>4490671.290 5322017.800 557.020</gml:upperCorner>
        </gml:Envelope>
    </gml:boundedBy>
    <cityObjectMember>
        <bldg:Building gml:id="DEBY_LOD2_5744682">
            <gml:name>DEBY_LOD2_5744682</gml:name>
            <creationDate>2014-10-08</creationDate>
            <bldg:function>31001_9998</bldg:function>
            <bldg:roofType>3100</bldg:roofType>
            <bldg:lod2Solid>
                <gml:Solid>
                    <gml:exterior>
                        <gml:CompositeSurface>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_1e36b54e-2518-4afe-a2b4-a59ddff93581_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_26de5877-57e7-429d-9b9a-274b8ed6aac5_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_314d7d2e-1551-4946-80a4-12e463d59de5_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_392cb098-6e22-4334-9853-1e8225966156_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_44e7c68d-da01-4f80-b1a4-9bbde8305c77_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_58e93bde-fd64-4fec-9626-5824c2e94f0e_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_5e13d1c8-7fb5-479f-9794-7b9e1f89ca1e_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_6a1b5359-d4e4-4d80-aeb8-ad63625a56dc_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_80ce6c2a-8724-4a2a-89e4-881da9530ecc_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_887068cb-0fcb-45f3-b436-d1a1bdef047f_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_dd1b367c-c6d8-4eb2-abe6-0accb0fa91b8_poly"/>
                        </gml:CompositeSurface>
                    </gml:exterior>
                </gml:Solid>
            </bldg:lod2Solid>
            <bldg:boundedBy>
                <bldg:RoofSurface gml:id="DEBY_LOD2_5744682_5e13d1c8-7fb5-479f-9794-7b9e1f89ca1e">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_5e13d1c8-7fb5-479f-9794-7b9e1f89ca1e_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490663.450 5322007.590 555.191 4490663.250 5322006.210 554.643 4490666.840 5322005.700 554.642 4490669.800 5322005.280 554.641 4490670.002 5322006.703 555.206 4490670.649 5322011.271 557.020 4490656.141 5322013.320 557.020 4490655.500 5322008.750 555.206 4490663.450 5322007.590 555.191</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:RoofSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:WallSurface gml:id="DEBY_LOD2_5744682_314d7d2e-1551-4946-80a4-12e463d59de5">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_314d7d2e-1551-4946-80a4-12e463d59de5_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490664.850 5322016.660 548.470 4490664.850 5322016.660 555.241 4490664.850 5322016.700 555.226 4490664.850 5322016.700 548.470 4490664.850 5322016.660 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:WallSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:WallSurface gml:id="DEBY_LOD2_5744682_6a1b5359-d4e4-4d80-aeb8-ad63625a56dc">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_6a1b5359-d4e4-4d80-aeb8-ad63625a56dc_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490664.850 5322016.700 548.470 4490664.850 5322016.700 555.226 4490671.290 5322015.790 555.226 4490671.290 5322015.790 548.470 4490664.850 5322016.700 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:WallSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:WallSurface gml:id="DEBY_LOD2_5744682_44e7c68d-da01-4f80-b1a4-9bbde8305c77">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_44e7c68d-da01-4f80-b1a4-9bbde8305c77_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490656.770 5322017.800 548.470 4490656.770 5322017.800 555.242 4490664.850 5322016.660 555.241 4490664.850 5322016.660 548.470 4490656.770 5322017.800 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:WallSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:WallSurface gml:id="DEBY_LOD2_5744682_1e36b54e-2518-4afe-a2b4-a59ddff93581">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_1e36b54e-2518-4afe-a2b4-a59ddff93581_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490663.250 5322006.210 548.470 4490663.250 5322006.210 554.643 4490663.450 5322007.590 555.191 4490663.450 5322007.590 548.470 4490663.250 5322006.210 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:WallSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:WallSurface gml:id="DEBY_LOD2_5744682_887068cb-0fcb-45f3-b436-d1a1bdef047f">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_887068cb-0fcb-45f3-b436-d1a1bdef047f_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490663.450 5322007.590 548.470 4490663.450 5322007.590 555.191 4490655.500 5322008.750 555.206 4490655.500 5322008.750 548.470 4490663.450 5322007.590 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:WallSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:WallSurface gml:id="DEBY_LOD2_5744682_80ce6c2a-8724-4a2a-89e4-881da9530ecc">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_80ce6c2a-8724-4a2a-89e4-881da9530ecc_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490670.002 5322006.703 555.206 4490669.800 5322005.280 554.641 4490669.800 5322005.280 548.470 4490670.002 5322006.703 548.470 4490670.649 5322011.271 548.470 4490671.290 5322015.790 548.470 4490671.290 5322015.790 555.226 4490670.649 5322011.271 557.020 4490670.002 5322006.703 555.206</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:WallSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:WallSurface gml:id="DEBY_LOD2_5744682_392cb098-6e22-4334-9853-1e8225966156">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_392cb098-6e22-4334-9853-1e8225966156_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490666.840 5322005.700 548.470 4490669.800 5322005.280 548.470 4490669.800 5322005.280 554.641 4490666.840 5322005.700 554.642 4490663.250 5322006.210 554.643 4490663.250 5322006.210 548.470 4490666.840 5322005.700 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:WallSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:RoofSurface gml:id="DEBY_LOD2_5744682_26de5877-57e7-429d-9b9a-274b8ed6aac5">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_26de5877-57e7-429d-9b9a-274b8ed6aac5_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490670.649 5322011.271 557.020 4490671.290 5322015.790 555.226 4490664.850 5322016.700 555.226 4490664.850 5322016.660 555.241 4490656.770 5322017.800 555.242 4490656.141 5322013.320 557.020 4490670.649 5322011.271 557.020</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:RoofSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:WallSurface gml:id="DEBY_LOD2_5744682_dd1b367c-c6d8-4eb2-abe6-0accb0fa91b8">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_dd1b367c-c6d8-4eb2-abe6-0accb0fa91b8_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490655.500 5322008.750 555.206 4490656.141 5322013.320 557.020 4490656.770 5322017.800 555.242 4490656.770 5322017.800 548.470 4490656.141 5322013.320 548.470 4490655.500 5322008.750 548.470 4490655.500 5322008.750 555.206</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:WallSurface>
            </bldg:boundedBy>
            <bldg:boundedBy>
                <bldg:GroundSurface gml:id="DEBY_LOD2_5744682_58e93bde-fd64-4fec-9626-5824c2e94f0e">
                    <bldg:lod2MultiSurface>
                        <gml:MultiSurface>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_58e93bde-fd64-4fec-9626-5824c2e94f0e_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490670.649 5322011.271 548.470 4490670.002 5322006.703 548.470 4490669.800 5322005.280 548.470 4490666.840 5322005.700 548.470 4490663.250 5322006.210 548.470 4490663.450 5322007.590 548.470 4490655.500 5322008.750 548.470 4490656.141 5322013.320 548.470 4490656.770 5322017.800 548.470 4490664.850 5322016.660 548.470 4490664.850 5322016.700 548.470 4490671.290 5322015.790 548.470 4490670.649 5322011.271 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </bldg:lod2MultiSurface>
                </bldg:GroundSurface>
            </bldg:boundedBy>
            <bldg:address>
                <Address gml:id="fme-gen-0355784d-2ffc-4c46-b812-c4d08d6a3f81">
                    <xalAddress>
                        <xAL:AddressDetails>
                            <xAL:Country>
                                <xAL:CountryName>Germany</xAL:CountryName>
                                <xAL:Locality Type="Town">
                                    <xAL:LocalityName>Moosach</xAL:LocalityName>
                                    <xAL:Thoroughfare Type="Street">
                                        <xAL:ThoroughfareName>Am Hang 15</xAL:ThoroughfareName>
                                    </xAL:Thoroughfare>
                                </xAL:Locality>
                            </xAL:Country>
                        </xAL:AddressDetails>
                    </xalAddress>
                </Address>
            </bldg:address>
        </bldg:Building>
    </cityObjectMember>
</CityModel>
